"""Velocity fields: following them from anywhere reaches the exit without entering an obstacle."""

from __future__ import annotations

import math

import numba
import numpy as np
import pytest

from grove_tui.navigation.grid import OccupancyGrid, build_grid
from grove_tui.navigation.theta_star import PlanCache, PlanningError, ThetaStarPlanner
from grove_tui.navigation.velocity_field import VelocityField, build_velocity_field, sample_field
from grove_tui.world import list_worlds, load_world

ARRIVED, ENTERED_OBSTACLE, STALLED, TOO_LONG = 0, 1, 2, 3


@numba.njit(cache=True)
def follow(vectors, origin_x, origin_y, resolution, occupied, x, y, exit_row, exit_col, step, max_steps):
    """Integrate the sampled field with fixed steps; report how the walk ended and where."""
    height, width = occupied.shape
    for k in range(max_steps):
        vx, vy = sample_field(vectors, origin_x, origin_y, resolution, x, y)
        if vx == 0.0 and vy == 0.0:
            return STALLED, x, y
        x += step * vx
        y += step * vy
        row = int(math.floor((y - origin_y) / resolution))
        col = int(math.floor((x - origin_x) / resolution))
        if row < 0 or row >= height or col < 0 or col >= width or occupied[row, col]:
            return ENTERED_OBSTACLE, x, y
        if abs(row - exit_row) <= 1 and abs(col - exit_col) <= 1:
            return ARRIVED, x, y
    return TOO_LONG, x, y


def assert_following_reaches_exit(grid, field, exit_cell, samples=200, seed=0):
    reachable = np.argwhere(field.reachable)
    rng = np.random.default_rng(seed)
    picks = reachable[rng.choice(len(reachable), size=min(samples, len(reachable)), replace=False)]
    step = 0.25 * grid.resolution
    max_steps = 40 * sum(grid.occupied.shape)
    for row, col in picks:
        cx, cy = grid.cell_to_world(row, col)
        x, y = cx + rng.uniform(-0.45, 0.45) * grid.resolution, cy + rng.uniform(-0.45, 0.45) * grid.resolution
        outcome, fx, fy = follow(field.vectors, field.origin[0], field.origin[1], field.resolution, grid.occupied,
                                 x, y, exit_cell[0], exit_cell[1], step, max_steps)
        names = {ENTERED_OBSTACLE: "entered an occupied cell", STALLED: "stalled", TOO_LONG: "never arrived"}
        assert outcome == ARRIVED, f"from ({x:.3f}, {y:.3f}) the walk {names.get(outcome)} at ({fx:.3f}, {fy:.3f})"


def make_grid(occupied, resolution=0.1) -> OccupancyGrid:
    return OccupancyGrid(origin=(0.0, 0.0), resolution=resolution, occupied=np.asarray(occupied, dtype=bool),
                         inflation=0.0, world_name="synthetic")


def three_rooms(n=60) -> np.ndarray:
    occupied = np.zeros((n, n), dtype=bool)
    occupied[0, :] = occupied[-1, :] = occupied[:, 0] = occupied[:, -1] = True
    occupied[n // 2, :] = True
    occupied[: n // 2, n // 2] = True
    occupied[n // 2, 8:12] = False
    occupied[10:14, n // 2] = False
    occupied[40:44, -1] = False  # the exit: a gap in the east wall of the top room
    occupied[15:20, 5:25] = True  # furniture in the bottom-left room
    occupied[45:48, 10:40] = True  # and in the top room
    occupied[4:8, 52:56] = True  # an enclosed pocket of free space, unreachable from the exit
    occupied[5:7, 53:55] = False
    return occupied


@pytest.fixture(scope="module")
def rooms_field():
    grid = make_grid(three_rooms())
    planner = ThetaStarPlanner(grid)
    exit_point = grid.cell_to_world(42, 59)
    path = planner.plan(grid.cell_to_world(5, 5), exit_point)
    return grid, planner, build_velocity_field(grid, path, exit_point, planner=planner), exit_point


def test_synthetic_rooms_every_cell_reaches_the_exit(rooms_field):
    grid, planner, field, exit_point = rooms_field
    assert_following_reaches_exit(grid, field, planner.cell_of(*exit_point), samples=400)


def test_vectors_are_unit_on_reachable_cells_and_zero_elsewhere(rooms_field):
    grid, planner, field, _ = rooms_field
    norms = np.hypot(field.vectors[..., 0], field.vectors[..., 1])
    reachable = field.reachable
    np.testing.assert_allclose(norms[reachable], 1.0, atol=1e-5)
    assert not reachable[grid.occupied].any()
    assert not reachable[5:7, 53:55].any(), "the enclosed pocket cannot reach the exit"
    expected = (~grid.occupied) & (planner.components == planner.components[42, 58])
    np.testing.assert_array_equal(reachable, expected)


def test_no_stored_vector_points_into_a_blocked_neighbour(rooms_field):
    _grid, _planner, field, _ = rooms_field
    usable = np.pad(field.reachable, 1)
    vx, vy = field.vectors[..., 0], field.vectors[..., 1]
    inside = field.reachable
    assert not np.any(inside & ~usable[1:-1, 2:] & (vx > 0)), "points east into an obstacle"
    assert not np.any(inside & ~usable[1:-1, :-2] & (vx < 0)), "points west into an obstacle"
    assert not np.any(inside & ~usable[2:, 1:-1] & (vy > 0)), "points north into an obstacle"
    assert not np.any(inside & ~usable[:-2, 1:-1] & (vy < 0)), "points south into an obstacle"


def test_field_follows_the_path_near_it(rooms_field):
    grid, _planner, field, _ = rooms_field
    # in the middle of a long open stretch, the field points along the path, not just at the exit
    a, b = field.path[0], field.path[1]
    middle = (a + b) / 2
    direction = (b - a) / np.linalg.norm(b - a)
    vx, vy = field.sample(*middle)
    assert vx * direction[0] + vy * direction[1] > 0.9


def test_sampling_is_bilinear_and_normalised():
    vectors = np.zeros((4, 4, 2), dtype=np.float32)
    vectors[..., 0] = 1.0
    assert sample_field(vectors, 0.0, 0.0, 1.0, 1.7, 2.2) == pytest.approx((1.0, 0.0))
    vectors[:, 2:, 0] = 0.0
    vectors[:, 2:, 1] = 1.0  # right half points north
    vx, vy = sample_field(vectors, 0.0, 0.0, 1.0, 2.0, 2.0)  # on the border between the halves
    assert (vx, vy) == pytest.approx((math.sqrt(0.5), math.sqrt(0.5)), abs=1e-6)
    vx, vy = sample_field(vectors, 0.0, 0.0, 1.0, 1.75, 2.0)  # a quarter cell east of column 1's centre
    assert vx > vy > 0 and math.hypot(vx, vy) == pytest.approx(1.0)


def test_inside_an_obstacle_the_field_points_back_to_free_space(rooms_field):
    grid, _planner, field, _ = rooms_field
    x, y = grid.cell_to_world(18, 15)  # inside the bottom-left furniture (rows 15-19)
    vx, vy = field.sample(x, y)
    assert math.hypot(vx, vy) == pytest.approx(1.0)
    assert vy > 0.5, "the nearest free cells are two rows up"


def test_save_and_load_round_trip(rooms_field, tmp_path):
    _grid, _planner, field, _ = rooms_field
    target = field.save(tmp_path / "field.npz")
    loaded = VelocityField.load(target)
    np.testing.assert_array_equal(loaded.vectors, field.vectors)
    np.testing.assert_array_equal(loaded.path, field.path)
    assert loaded.origin == field.origin and loaded.resolution == field.resolution and loaded.exit == field.exit
    (tmp_path / "broken.npz").write_bytes(b"not a zip")
    from grove_tui.navigation.velocity_field import FieldFileError

    # A broken file is bad input (exit 2), not a planning failure.
    with pytest.raises(FieldFileError, match="broken.npz"):
        VelocityField.load(tmp_path / "broken.npz")


def test_exit_inside_an_obstacle_is_an_error_naming_it(rooms_field):
    grid, planner, _field, _ = rooms_field
    with pytest.raises(PlanningError, match="fire_door"):
        build_velocity_field(grid, np.empty((0, 2)), grid.cell_to_world(17, 15), exit_label="fire_door",
                             planner=planner)


def test_plan_cache_builds_a_field_once(rooms_field):
    grid, planner, _field, exit_point = rooms_field
    cache = PlanCache()
    first = cache.field("rooms", planner, grid.cell_to_world(5, 5), exit_point)
    assert cache.field("rooms", planner, grid.cell_to_world(5, 5), exit_point) is first


# ---- every shipped world and every exit ---------------------------------------------------------


@pytest.mark.slow
@pytest.mark.parametrize("name", list_worlds())
def test_world_fields_lead_every_cell_to_each_exit(name):
    world = load_world(name)
    grid = build_grid(world, resolution=0.1)
    planner = ThetaStarPlanner(grid, landmarks=0)  # fields use only the grid maps
    exits = world.exits()
    assert exits, f"world {name} has no exit"
    start = world.zones[len(world.zones) // 2].anchor
    for door in exits:
        exit_point = door.inward_point(0.6)
        path = planner.plan(start, exit_point, start_label="group", goal_label=door.name)
        field = build_velocity_field(grid, path, exit_point, exit_label=door.name, planner=planner)
        exit_cell = planner.snap(*exit_point, door.name, "exit")
        np.testing.assert_array_equal(field.reachable, planner.components == planner.components[exit_cell])
        assert_following_reaches_exit(grid, field, exit_cell, samples=120)


def _open_planner(width: float = 30.0, height: float = 10.0, resolution: float = 0.1) -> ThetaStarPlanner:
    """An empty walled room as a grid (no world needed): walls one cell thick all round."""
    cols, rows = int(width / resolution), int(height / resolution)
    occupied = np.zeros((rows, cols), dtype=bool)
    occupied[0, :] = occupied[-1, :] = occupied[:, 0] = occupied[:, -1] = True
    return ThetaStarPlanner(OccupancyGrid((0.0, 0.0), resolution, occupied, 0.0), landmarks=0)


def test_least_congested_exits_send_people_to_the_far_door_only_when_the_near_queue_is_longer():
    from grove_tui.navigation.velocity_field import exit_walks, least_congested_exits, nearest_exits

    planner = _open_planner()
    exits = {"west": ((0.5, 5.0), 1.0), "east": ((29.5, 5.0), 1.0)}
    crowd = [(2.0 + 0.5 * (k % 10), 2.0 + 0.6 * (k // 10)) for k in range(100)]  # all by the west door
    names, walks = exit_walks(planner, {n: p for n, (p, _w) in exits.items()}, crowd[:1])
    assert walks[names.index("west"), 0] == pytest.approx(math.dist((2.0, 2.0), (0.5, 5.0)), abs=0.2)  # metres
    assert set(nearest_exits(planner, {n: p for n, (p, _w) in exits.items()}, crowd)) == {"west"}
    chosen = least_congested_exits(planner, exits, crowd, [1.34] * len(crowd))
    # a 27 m detour (about 20 s) pays off once ~30 people queue at a 1 m door (1.6 /s); the west door
    # drains from the start, the east one only once walkers arrive, so the west keeps more
    assert 15 < chosen.count("east") < 50 < chosen.count("west")
    # the first to reach the west door, before any queue could form there, all take it
    west_walk = exit_walks(planner, {"west": (0.5, 5.0)}, crowd)[1][0]
    first = np.argsort(west_walk, kind="stable")[:20]
    assert all(chosen[k] == "west" for k in first)
    # a handful of people never walk to the far door: there is no queue worth avoiding
    few = least_congested_exits(planner, exits, crowd[:5], [1.34] * 5)
    assert few == ["west"] * 5
    # a wider door drains faster, so it takes more of them
    wide = least_congested_exits(planner, {"west": ((0.5, 5.0), 1.0), "east": ((29.5, 5.0), 3.0)}, crowd,
                                 [1.34] * len(crowd))
    assert wide.count("east") > chosen.count("east")
