"""Theta*: collision-free any-angle paths never longer than 8-connected A*, clear errors, caching."""

from __future__ import annotations

import heapq
import math

import numba
import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from grove_tui.errors import GroveError
from grove_tui.navigation.grid import OccupancyGrid, build_grid
from grove_tui.navigation.theta_star import (
    PlanCache,
    PlanningError,
    ThetaStarPlanner,
    clearance_map,
    line_of_sight,
    path_length,
    sight_maps,
)
from grove_tui.world import list_worlds, load_world

WORLDS = list_worlds()


# ---- independent oracles -----------------------------------------------------------------------


def segment_hits_occupied(grid: OccupancyGrid, a, b) -> bool:
    """Brute force: does the world segment a-b meet (even touch) the closed square of any occupied cell?

    Liang-Barsky clipping of the segment against every cell square in its bounding box.
    """
    res = grid.resolution
    x0, y0 = grid.origin
    ax, ay = (a[0] - x0) / res, (a[1] - y0) / res  # cell units, cell (r, c) = [c, c+1] x [r, r+1]
    bx, by = (b[0] - x0) / res, (b[1] - y0) / res
    c_lo, c_hi = int(math.floor(min(ax, bx))) - 1, int(math.floor(max(ax, bx))) + 1
    r_lo, r_hi = int(math.floor(min(ay, by))) - 1, int(math.floor(max(ay, by))) + 1
    rows, cols = np.mgrid[r_lo:r_hi + 1, c_lo:c_hi + 1]
    rows, cols = rows.ravel(), cols.ravel()
    height, width = grid.occupied.shape
    inside = (rows >= 0) & (rows < height) & (cols >= 0) & (cols < width)
    blocked = np.ones(rows.shape, dtype=bool)
    blocked[inside] = grid.occupied[rows[inside], cols[inside]]
    rows, cols = rows[blocked], cols[blocked]
    if len(rows) == 0:
        return False
    dx, dy = bx - ax, by - ay
    t0 = np.zeros(len(rows))
    t1 = np.ones(len(rows))
    eps = 1e-9
    for p, lo_edge, hi_edge, start in ((dx, cols, cols + 1, ax), (dy, rows, rows + 1, ay)):
        if abs(p) < 1e-15:
            outside = (start < lo_edge - eps) | (start > hi_edge + eps)
            t1 = np.where(outside, -1.0, t1)
        else:
            ta = (lo_edge - eps - start) / p
            tb = (hi_edge + eps - start) / p
            t0 = np.maximum(t0, np.minimum(ta, tb))
            t1 = np.minimum(t1, np.maximum(ta, tb))
    return bool(np.any(t0 <= t1))


@numba.njit(cache=True)
def _octile_astar(occupied, sr, sc, gr, gc):
    height, width = occupied.shape
    dist = np.full(height * width, np.inf)
    start = sr * width + sc
    goal = gr * width + gc
    dist[start] = 0.0
    heap = [(0.0, start)]
    while len(heap) > 0:
        _f, node = heapq.heappop(heap)
        if node == goal:
            return dist[goal]
        r, c = node // width, node % width
        for dr in (-1, 0, 1):
            for dc in (-1, 0, 1):
                if dr == 0 and dc == 0:
                    continue
                nr, nc = r + dr, c + dc
                if nr < 0 or nr >= height or nc < 0 or nc >= width or occupied[nr, nc]:
                    continue
                if dr != 0 and dc != 0 and (occupied[r, nc] or occupied[nr, c]):
                    continue  # no corner cutting, as in the planner
                nd = dist[node] + (math.sqrt(2.0) if dr != 0 and dc != 0 else 1.0)
                nb = nr * width + nc
                if nd < dist[nb]:
                    dist[nb] = nd
                    ddr, ddc = abs(gr - nr), abs(gc - nc)
                    h = max(ddr, ddc) + (math.sqrt(2.0) - 1.0) * min(ddr, ddc)
                    heapq.heappush(heap, (nd + h, nb))
    return np.inf


def reference_astar_length(grid, start_cell, goal_cell) -> float:
    """Shortest 8-connected grid path between two cell centres, in metres."""
    return _octile_astar(grid.occupied, start_cell[0], start_cell[1], goal_cell[0], goal_cell[1]) * grid.resolution


def make_grid(occupied, resolution=0.1, origin=(0.0, 0.0), inflation=0.0, name="synthetic") -> OccupancyGrid:
    return OccupancyGrid(origin=origin, resolution=resolution, occupied=np.asarray(occupied, dtype=bool),
                         inflation=inflation, world_name=name)


def assert_collision_free(grid, path):
    for a, b in zip(path[:-1], path[1:]):
        assert not segment_hits_occupied(grid, a, b), f"segment {a} -> {b} touches an occupied cell"


# ---- synthetic grids ---------------------------------------------------------------------------


def rooms_with_doors(n=60) -> np.ndarray:
    occupied = np.zeros((n, n), dtype=bool)
    occupied[0, :] = occupied[-1, :] = occupied[:, 0] = occupied[:, -1] = True
    occupied[n // 2, :] = True
    occupied[:, n // 2] = True
    occupied[n // 2, 5:9] = False  # door between the two left rooms
    occupied[40:44, n // 2] = False  # door between the two top rooms
    occupied[n // 2, 45:49] = False  # door between the two right rooms
    return occupied


def maze(cells=12, seed=3) -> np.ndarray:
    rng = np.random.default_rng(seed)
    size = 2 * cells + 1
    occupied = np.ones((size, size), dtype=bool)
    seen = np.zeros((cells, cells), dtype=bool)
    stack = [(0, 0)]
    seen[0, 0] = True
    occupied[1, 1] = False
    while stack:
        r, c = stack[-1]
        options = [(r + dr, c + dc) for dr, dc in ((0, 1), (1, 0), (0, -1), (-1, 0))
                   if 0 <= r + dr < cells and 0 <= c + dc < cells and not seen[r + dr, c + dc]]
        if not options:
            stack.pop()
            continue
        nr, nc = options[rng.integers(len(options))]
        seen[nr, nc] = True
        occupied[2 * nr + 1, 2 * nc + 1] = False
        occupied[r + nr + 1, c + nc + 1] = False
        stack.append((nr, nc))
    return np.repeat(np.repeat(occupied, 2, axis=0), 2, axis=1)  # corridors two cells wide


def random_rectangles(n=150, count=60, seed=1) -> np.ndarray:
    rng = np.random.default_rng(seed)
    occupied = np.zeros((n, n), dtype=bool)
    for _ in range(count):
        r, c = rng.integers(0, n, 2)
        h, w = rng.integers(1, 18, 2)
        occupied[r:r + h, c:c + w] = True
    return occupied


def test_open_ground_gives_the_straight_segment():
    grid = make_grid(np.zeros((50, 80), dtype=bool))
    path = ThetaStarPlanner(grid).plan((0.33, 0.41), (7.62, 4.27))
    np.testing.assert_allclose(path, [[0.33, 0.41], [7.62, 4.27]])


def test_path_goes_through_the_door_and_is_any_angle():
    grid = make_grid(rooms_with_doors())
    planner = ThetaStarPlanner(grid)
    start, goal = grid.cell_to_world(10, 10), grid.cell_to_world(50, 12)  # bottom-left room to top-left room
    path = planner.plan(start, goal)
    assert_collision_free(grid, path)
    assert len(path) >= 3, "a wall lies between the rooms: the path must bend at the door"
    crossing = [(a, b) for a, b in zip(path[:-1], path[1:]) if (a[1] - 3.05) * (b[1] - 3.05) < 0]
    assert len(crossing) == 1, f"the path should cross the wall row once: {path}"
    (ax, ay), (bx, by) = crossing[0]
    assert 0.5 <= ax + (3.05 - ay) * (bx - ax) / (by - ay) <= 0.9, "the crossing is the door (x 0.5-0.9 m)"
    # any-angle: no more vertices than needed and strictly shorter than the 8-connected grid path
    assert path_length(path) < reference_astar_length(grid, (10, 10), (50, 12)) - 1e-6


def test_maze_paths_match_or_beat_astar_and_stay_in_corridors():
    grid = make_grid(maze())
    planner = ThetaStarPlanner(grid)
    free = np.argwhere(~grid.occupied)
    rng = np.random.default_rng(7)
    for _ in range(30):
        a, b = free[rng.integers(len(free))], free[rng.integers(len(free))]
        path = planner.plan(grid.cell_to_world(*a), grid.cell_to_world(*b))
        assert_collision_free(grid, path)
        assert path_length(path) <= reference_astar_length(grid, a, b) + 1e-9


def test_diagonal_squeeze_between_two_corners_is_refused():
    occupied = np.zeros((10, 10), dtype=bool)
    occupied[:5, 5] = True  # lower wall ends at row 4
    occupied[5:, 4] = True  # upper wall starts at row 5, one column to the left: only a corner touch
    grid = make_grid(occupied)
    with pytest.raises(PlanningError):
        ThetaStarPlanner(grid).plan(grid.cell_to_world(2, 2), grid.cell_to_world(7, 7))


def test_line_of_sight_agrees_with_brute_force_on_random_segments():
    grid = make_grid(random_rectangles(80, 30, seed=5), resolution=1.0)
    sight = sight_maps(clearance_map(grid.occupied))
    free = np.argwhere(~grid.occupied)
    rng = np.random.default_rng(11)
    clear_seen = blocked_seen = 0
    for _ in range(3000):
        (r0, c0), (r1, c1) = free[rng.integers(len(free))], free[rng.integers(len(free))]
        expected = not segment_hits_occupied(grid, grid.cell_to_world(r0, c0), grid.cell_to_world(r1, c1))
        assert line_of_sight(*sight, r0, c0, r1, c1) == expected, (r0, c0, r1, c1)
        clear_seen += expected
        blocked_seen += not expected
    assert clear_seen > 100 and blocked_seen > 100


def test_exact_corner_touch_blocks_line_of_sight():
    occupied = np.zeros((5, 5), dtype=bool)
    occupied[2, 3] = True  # the 45-degree segment (1,1)-(3,3) meets this cell only at its corner (2.5, 2.5)
    sight = sight_maps(clearance_map(occupied))
    assert not line_of_sight(*sight, 1, 1, 3, 3)
    assert line_of_sight(*sight, 1, 1, 1, 4)


def test_unreachable_goal_names_both_labels():
    occupied = np.zeros((20, 20), dtype=bool)
    occupied[:, 10] = True
    grid = make_grid(occupied)
    with pytest.raises(PlanningError) as error:
        ThetaStarPlanner(grid).plan((0.5, 0.5), (1.55, 0.5),
                                    start_label="pharmacy", goal_label="west_wing_bed_3")
    assert "pharmacy" in str(error.value) and "west_wing_bed_3" in str(error.value)
    assert isinstance(error.value, GroveError)


def test_start_deep_inside_an_obstacle_is_an_error_naming_it():
    occupied = np.zeros((20, 20), dtype=bool)
    occupied[5:15, 5:15] = True
    grid = make_grid(occupied)
    with pytest.raises(PlanningError, match="reception_counter.*inside an obstacle"):
        ThetaStarPlanner(grid).plan((1.0, 1.0), (0.2, 0.2), start_label="reception_counter")
    with pytest.raises(PlanningError, match="goal 'vending_machine'"):
        ThetaStarPlanner(grid).plan((0.2, 0.2), (1.0, 1.0), goal_label="vending_machine")
    with pytest.raises(PlanningError, match="outside the grid"):
        ThetaStarPlanner(grid).plan((-3.0, 0.5), (0.2, 0.2))


def test_endpoint_within_one_cell_of_free_space_snaps():
    occupied = np.zeros((20, 20), dtype=bool)
    occupied[5:15, 5:15] = True
    grid = make_grid(occupied)
    planner = ThetaStarPlanner(grid)
    start = (0.53, 1.04)  # cell (10, 5): occupied, its west neighbour is free
    path = planner.plan(start, (0.2, 1.0))
    np.testing.assert_allclose(path[0], start)
    np.testing.assert_allclose(path[1], grid.cell_to_world(10, 4))
    np.testing.assert_allclose(path[-1], (0.2, 1.0))
    assert_collision_free(grid, path[1:])


def test_paths_are_deterministic_and_buffers_reusable():
    grid = make_grid(random_rectangles())
    planner = ThetaStarPlanner(grid)
    free = np.argwhere(~grid.occupied)
    pairs = [(free[i], free[-i - 1]) for i in range(0, 2000, 400)]
    first = [planner.plan_cells(tuple(a), tuple(b)) for a, b in pairs]
    again = [planner.plan_cells(tuple(a), tuple(b)) for a, b in reversed(pairs)][::-1]
    for x, y in zip(first, again):
        np.testing.assert_array_equal(x, y)


# ---- every shipped world ------------------------------------------------------------------------


@pytest.fixture(scope="module", params=WORLDS)
def world_planner(request):
    grid = build_grid(load_world(request.param), resolution=0.1)
    # with the landmark heuristic on: the "no longer than A*" guarantee rests on its admissibility
    return grid, ThetaStarPlanner(grid, landmarks=8), np.argwhere(~grid.occupied)


@pytest.mark.slow
@settings(max_examples=20, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(data=st.data())
def test_world_paths_are_collision_free_and_no_longer_than_astar(world_planner, data):
    grid, planner, free = world_planner
    a = free[data.draw(st.integers(0, len(free) - 1), label="start cell")]
    b = free[data.draw(st.integers(0, len(free) - 1), label="goal cell")]
    # anywhere inside the free start/goal cells, not just at their centres
    offsets = [data.draw(st.floats(-0.49, 0.49), label="offset") * grid.resolution for _ in range(4)]
    ca, cb = grid.cell_to_world(*a), grid.cell_to_world(*b)
    start, goal = (ca[0] + offsets[0], ca[1] + offsets[1]), (cb[0] + offsets[2], cb[1] + offsets[3])
    reference = reference_astar_length(grid, a, b)
    if not np.isfinite(reference):
        with pytest.raises(PlanningError):
            planner.plan(start, goal)
        return
    centres = planner.plan(ca, cb)
    assert_collision_free(grid, centres)
    assert path_length(centres) <= reference + 1e-9
    path = planner.plan(start, goal)
    np.testing.assert_allclose(path[0], start)
    np.testing.assert_allclose(path[-1], goal)
    assert_collision_free(grid, path)
    slack = math.dist(start, ca) + math.dist(goal, cb)
    assert path_length(path) <= reference + slack + 1e-9


def test_world_paths_from_every_entity_to_the_first_exit(world_planner):
    grid, planner, _free = world_planner
    world = load_world(grid.world_name)
    exit_point = world.exits()[0].inward_point(0.6)
    for entity in world.entities():
        path = planner.plan(entity.interaction_point, exit_point, start_label=entity.name, goal_label="exit")
        # an endpoint inside (or on the border of) an occupied cell joins the path through the nearest
        # free cell centre: only that short first/last segment may touch the obstacle
        first = 1 if segment_hits_occupied(grid, entity.interaction_point, entity.interaction_point) else 0
        last = len(path) - 1 if segment_hits_occupied(grid, exit_point, exit_point) else len(path)
        assert_collision_free(grid, path[first:last])
        assert path_length(path) >= math.dist(entity.interaction_point, exit_point) - 1e-9


# ---- cache --------------------------------------------------------------------------------------


def test_plan_cache_reuses_plans_per_world_resolution_and_endpoints():
    grid = make_grid(rooms_with_doors())
    planner = ThetaStarPlanner(grid)
    cache = PlanCache(max_entries=2)
    first = cache.plan("rooms", planner, (1.0, 1.0), (5.0, 5.0))
    assert cache.plan("rooms", planner, (1.001, 1.0), (5.0, 5.0)) is first  # same to the centimetre
    assert (cache.hits, cache.misses) == (1, 1)
    assert cache.plan("other_world", planner, (1.0, 1.0), (5.0, 5.0)) is not first
    coarse = ThetaStarPlanner(make_grid(rooms_with_doors(), resolution=0.2))
    cache.plan("rooms", coarse, (1.0, 1.0), (5.0, 5.0))
    assert len(cache) == 2  # bounded: the oldest entry went
    assert cache.plan("rooms", planner, (1.0, 1.0), (5.0, 5.0)) is not first
    with pytest.raises(ValueError):
        first[0, 0] = 9.0  # cached paths are read-only so callers cannot corrupt them


def test_landmark_heuristic_never_exceeds_the_grid_distance():
    grid = make_grid(maze(8, seed=9))
    planner = ThetaStarPlanner(grid, landmarks=4)
    free = np.argwhere(~grid.occupied)
    rng = np.random.default_rng(2)
    goal = tuple(free[rng.integers(len(free))])
    assert planner.landmarks.shape == (grid.occupied.size, 4)
    for cell in free[rng.choice(len(free), 60, replace=False)]:
        bound = planner.landmark_bound(tuple(cell), goal)
        assert bound <= reference_astar_length(grid, cell, goal) / grid.resolution
    # and the landmarks carry information: in a maze the bound beats the straight-line distance
    far = max(free, key=lambda c: planner.landmark_bound(tuple(c), goal))
    assert planner.landmark_bound(tuple(far), goal) > math.dist(far, goal) * 1.5


def test_plan_cache_keeps_one_planner_per_grid():
    grid = make_grid(rooms_with_doors())
    cache = PlanCache()
    planner = cache.planner(grid, landmarks=2)
    assert cache.planner(grid) is planner
    other = make_grid(rooms_with_doors(), resolution=0.2)
    assert cache.planner(other, landmarks=0) is not planner
