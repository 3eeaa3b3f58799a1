"""Occupancy grids: known cells, exact inflation, reachability of every zone, queries, save/load."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest
import shapely
from scipy import ndimage
from shapely.geometry import MultiLineString

from grove_tui.navigation import grid as grid_module
from grove_tui.navigation.grid import GridError, OccupancyGrid, build_grid
from grove_tui.world import World, load_world, parse_world

SHIPPED = ("hospital", "office", "residential", "airport", "station")


def components(grid: OccupancyGrid) -> np.ndarray:
    # 4-connectivity (ndimage.label's default) is stricter than any 8-connected planner.
    labels, _ = ndimage.label(~grid.occupied)
    return labels


def label_at(grid, labels, point) -> int:
    row, col = grid.world_to_cell(*point)
    return int(labels[row, col])


@pytest.mark.parametrize("resolution", (0.1, 0.05))
@pytest.mark.parametrize("name", SHIPPED)
def test_every_zone_door_and_entity_is_reachable_on_the_inflated_grid(name, resolution):
    world = load_world(name)
    grid = build_grid(world, resolution=resolution, inflation=0.35)
    labels = components(grid)
    start = label_at(grid, labels, world.zones[0].anchor)
    assert start != 0, "first zone's anchor is not free"
    for zone in world.zones:
        assert label_at(grid, labels, zone.anchor) == start, f"zone {zone.name} cut off"
    for door in world.doors():
        assert label_at(grid, labels, door.inward_point(0.6)) == start, f"door {door.name} blocked"
        if door.leads_to != "outside":
            assert label_at(grid, labels, door.outward_point(0.6)) == start, f"door {door.name} blocked"
    for entity in world.entities():
        assert label_at(grid, labels, entity.interaction_point) == start, f"entity {entity.name} unreachable"


def test_known_cells_in_the_hospital():
    world = load_world("hospital")
    grid = build_grid(world, resolution=0.05, inflation=0.35)
    assert not grid.is_free(12.0, 10.0)  # wall between radiology and the main waiting room
    assert not grid.is_free(12.2, 10.0)  # 0.2 m from that wall: inside the inflation
    assert grid.is_free(12.6, 10.0)  # 0.6 m away: free
    assert grid.is_free(32.0, 16.0)  # middle of the 4 m lobby-corridor opening
    assert grid.is_free(24.0, 8.0)  # middle of the waiting room door
    assert grid.is_free(*world.zone("entrance_lobby").anchor)
    assert grid.is_free(*world.zone("pharmacy").centroid)
    assert not grid.is_free(49.6, 8.0)  # inside the pharmacy counter
    assert not grid.is_free(-0.5, 5.0)  # outside the building
    assert not grid.is_free(32.0, -0.3)  # just outside the main entrance: outside every zone
    assert not grid.is_free(1000.0, 1000.0)  # outside the grid


def test_inflation_matches_exact_segment_distance():
    world = load_world("hospital")
    grid = build_grid(world, resolution=0.1, inflation=0.35)
    rng = np.random.default_rng(7)
    rows, cols = np.nonzero(np.ones_like(grid.occupied))
    pick = rng.choice(len(rows), size=4000, replace=False)
    xs = grid.origin[0] + (cols[pick] + 0.5) * grid.resolution
    ys = grid.origin[1] + (rows[pick] + 0.5) * grid.resolution
    walls = MultiLineString([((s[0], s[1]), (s[2], s[3])) for s in world.walls()])
    distance = shapely.distance(walls, shapely.points(xs, ys))
    in_zone = shapely.contains_xy(world.outline(), xs, ys)
    in_footprint = np.zeros(len(xs), dtype=bool)
    for entity in world.entities():
        in_footprint |= shapely.contains_xy(entity.polygon, xs, ys)
    for obstacle in world.obstacles:
        in_footprint |= shapely.contains_xy(obstacle.polygon, xs, ys)
    expected_occupied = ~in_zone | in_footprint | (distance <= 0.35)
    margin = np.abs(distance - 0.35) > 1e-6  # skip cells exactly on the inflation edge
    assert np.array_equal(grid.occupied[rows[pick], cols[pick]][margin], expected_occupied[margin])


def test_grid_geometry_and_cell_conversions():
    world = load_world("hospital")
    grid = build_grid(world, resolution=0.1)
    assert grid.occupied.dtype == bool
    xmin, ymin, xmax, ymax = grid.extent()
    assert xmin < 0 and ymin < 0 and xmax > 64 and ymax > 44
    row, col = grid.world_to_cell(10.03, 20.07)
    assert grid.cell_to_world(row, col) == pytest.approx((10.05, 20.05))
    assert grid.occupied.shape == (grid.height, grid.width)
    cells = grid.free_cells()
    assert cells.shape[1] == 2 and len(cells) == int((~grid.occupied).sum())
    assert not grid.occupied[cells[:, 0], cells[:, 1]].any()


def test_nearest_free():
    world = load_world("hospital")
    grid = build_grid(world, resolution=0.1, inflation=0.35)
    assert grid.nearest_free(20.0, 13.0) == (20.0, 13.0)  # already free: unchanged
    snapped = grid.nearest_free(49.6, 8.0)  # inside the pharmacy counter
    assert snapped is not None and grid.is_free(*snapped)
    assert np.hypot(snapped[0] - 49.6, snapped[1] - 8.0) < 1.1
    assert grid.nearest_free(49.6, 8.0, max_dist=0.2) is None
    far = grid.nearest_free(-20.0, 5.0)  # outside the grid: nearest free cell overall
    assert far is not None and grid.is_free(*far) and far[0] < 1.5
    assert grid.nearest_free(-20.0, 5.0, max_dist=5.0) is None


DIAGONAL = """\
name: diagonal
zones:
  - name: lower
    type: room
    boundary: [[0, 0], [6, 0], [6, 4]]
    doors: [{name: gap, position: [3, 2], width: 1.2, leads_to: upper}]
  - name: upper
    type: room
    boundary: [[0, 0], [6, 4], [0, 4]]
"""


def test_walls_block_even_without_inflation():
    world, problems = parse_world(DIAGONAL, "diagonal.yaml")
    assert problems == []
    grid = build_grid(world, resolution=0.1, inflation=0.0)
    labels = components(grid)
    assert label_at(grid, labels, (4.5, 1.0)) == label_at(grid, labels, (1.5, 3.0)) != 0
    # The same rooms without the door: a thin diagonal wall must not leak between cells.
    closed = World("diagonal_closed", "", [replace(zone, doors=()) for zone in world.zones])
    closed_grid = build_grid(closed, resolution=0.1, inflation=0.0)
    labels = components(closed_grid)
    lower, upper = label_at(closed_grid, labels, (4.5, 1.0)), label_at(closed_grid, labels, (1.5, 3.0))
    assert lower != 0 and upper != 0 and lower != upper
    labels8, _ = ndimage.label(~closed_grid.occupied, structure=np.ones((3, 3)))
    assert label_at(closed_grid, labels8, (4.5, 1.0)) != label_at(closed_grid, labels8, (1.5, 3.0))


def test_mini_world_rooms_split_without_their_door():
    text = """\
name: split
zones:
  - name: left
    type: room
    boundary: [[0, 0], [4, 0], [4, 3], [0, 3]]
    doors: [{name: link, position: [4, 1.5], width: 1.2, leads_to: right}]
  - name: right
    type: room
    boundary: [[4, 0], [8, 0], [8, 3], [4, 3]]
"""
    world, problems = parse_world(text, "split.yaml")
    assert problems == []
    open_grid = build_grid(world, resolution=0.05, inflation=0.35)
    labels = components(open_grid)
    assert label_at(open_grid, labels, (2, 1.5)) == label_at(open_grid, labels, (6, 1.5)) != 0
    narrow, _ = parse_world(text.replace("width: 1.2", "width: 0.6"), "narrow.yaml")
    narrow_grid = build_grid(narrow, resolution=0.05, inflation=0.35)  # 0.6 m < 2 x 0.35 m: closed
    labels = components(narrow_grid)
    assert label_at(narrow_grid, labels, (2, 1.5)) != label_at(narrow_grid, labels, (6, 1.5))


def test_grids_are_cached_and_read_only():
    world = load_world("hospital")
    first = build_grid(world, resolution=0.1, inflation=0.35)
    assert build_grid(world, 0.1, 0.35) is first
    assert build_grid(world, 0.1, 0.3) is not first
    with pytest.raises(ValueError):
        first.occupied[0, 0] = False
    with pytest.raises(GridError):
        build_grid(world, resolution=0.0)


def test_save_and_load_round_trip(tmp_path):
    world = load_world("hospital")
    grid = build_grid(world, resolution=0.1)
    path = grid.save(tmp_path / "grid.npz")
    loaded = OccupancyGrid.load(path)
    assert loaded.origin == grid.origin and loaded.resolution == grid.resolution
    assert loaded.inflation == grid.inflation and loaded.world_name == "hospital"
    assert np.array_equal(loaded.occupied, grid.occupied)
    (tmp_path / "junk.npz").write_bytes(b"not a grid")
    with pytest.raises(GridError, match="junk.npz"):
        OccupancyGrid.load(tmp_path / "junk.npz")


def test_hospital_rasterizes_at_five_centimetres():
    # how fast: bench/worlds.py
    grid = grid_module._rasterize(load_world("hospital"), 0.05, 0.35)
    assert grid.occupied.shape[0] * grid.occupied.shape[1] > 1_000_000
    assert 0.1 < grid.occupied.mean() < 0.5
