"""The door graph (issue 32): plans between zones through cached door-to-door paths, exit walks, shared trees."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from grove_tui.bt.format.ports import format_point_list, parse_point_list
from grove_tui.navigation import theta_star
from grove_tui.navigation.grid import build_grid
from grove_tui.navigation.theta_star import ThetaStarPlanner, path_length
from grove_tui.navigation.velocity_field import exit_walks
from grove_tui.world import load_world


@pytest.fixture(scope="module")
def residential():
    world = load_world("residential")
    return world, build_grid(world, resolution=0.1)


def free_points(grid, count, seed):
    free = np.argwhere(~grid.occupied)
    rng = np.random.default_rng(seed)
    return [grid.cell_to_world(*free[k]) for k in rng.integers(0, len(free), count)]


def test_plans_between_zones_go_through_doors_collision_free_and_tight(residential, tmp_path):
    world, grid = residential
    planner = ThetaStarPlanner(grid, world=world, door_graph_dir=tmp_path)
    exact = ThetaStarPlanner(dataclasses.replace(grid, world=None), landmarks=4)
    graph = planner.door_graph
    assert graph is not None and len(graph.door_names) == len(world.doors())
    between, longer = 0, []
    points = free_points(grid, 60, 1)
    for a, b in zip(points[::2], points[1::2]):
        cells = planner.snap(*a, "a", "start"), planner.snap(*b, "b", "goal")
        through = graph.plan(*cells)
        path = planner.plan(a, b)
        # written as waypoints (two decimals) the path still misses every obstacle
        rounded = [tuple(p) for p in parse_point_list(format_point_list(path[1:-1]))]
        for u, v in zip([a, *rounded], [*rounded, b]):
            assert planner.segment_is_free(*u, *v), (a, b, u, v)
        if through is not None:
            between += 1
            longer.append(path_length(path) / path_length(exact.plan(a, b)))
    assert between >= 10  # the sample crosses rooms
    assert np.mean(longer) <= 1.02 and max(longer) <= 1.06, longer


def test_the_graph_is_cached_in_the_data_dir_and_a_broken_cache_is_rebuilt(residential, tmp_path):
    world, grid = residential
    built = ThetaStarPlanner(grid, world=world, door_graph_dir=tmp_path).door_graph
    files = list(tmp_path.glob("residential_*.npz"))
    assert len(files) == 1 and not built.built_from_cache
    loaded = ThetaStarPlanner(dataclasses.replace(grid), world=world, door_graph_dir=tmp_path).door_graph
    assert loaded.built_from_cache and loaded.key == built.key
    np.testing.assert_array_equal(loaded.distance, built.distance)
    files[0].write_bytes(b"not an npz")
    rebuilt = ThetaStarPlanner(dataclasses.replace(grid), world=world, door_graph_dir=tmp_path).door_graph
    assert not rebuilt.built_from_cache
    np.testing.assert_array_equal(rebuilt.distance, built.distance)


def test_exit_walks_through_the_graph_match_the_exits_trees(residential, tmp_path):
    world, grid = residential
    exits = {d.name: d.position for d in world.exits()}
    starts = free_points(grid, 30, 2)
    with_graph = ThetaStarPlanner(grid, world=world, door_graph_dir=tmp_path)
    names, walks = exit_walks(with_graph, exits, starts)
    plain_names, plain = exit_walks(ThetaStarPlanner(dataclasses.replace(grid, world=None)), exits, starts)
    assert names == plain_names
    reachable = np.isfinite(plain)
    # the graph's walks pass door centres: a little longer, never shorter than the geodesic
    # (the graph snaps a door to a cell of all its zones: up to a cell off the exit tree's root)
    assert np.all(walks[reachable] >= plain[reachable] - grid.resolution)
    assert np.all(walks[reachable] <= plain[reachable] * 1.15 + 1.0)


def test_many_plans_to_one_goal_share_its_shortest_path_tree(residential):
    world, grid = residential
    planner = ThetaStarPlanner(dataclasses.replace(grid, world=None))
    goal = world.entities()[0].interaction_point
    starts = free_points(grid, theta_star.TREE_AFTER + 6, 3)
    lengths = []
    for start in starts:
        try:
            path = planner.plan(start, goal)
        except theta_star.PlanningError:
            continue
        assert math.dist(path[0], start) < 1e-9 and math.dist(path[-1], goal) < 1e-9
        assert all(planner.segment_is_free(*u, *v) for u, v in zip(path[1:-2], path[2:-1]))
        lengths.append(path_length(path))
    goal_cell = planner.snap(*goal, "goal", "goal")
    assert goal_cell in planner._shared.geodesics  # the later plans were read off the goal's tree
    assert len(lengths) > theta_star.TREE_AFTER
