"""The map rasteriser: braille walls, labels, doors, overlays, velocity-field arrows, agents and the robot."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pytest

from helpers.two_rooms import TWO_ROOMS

from grove_tui.world import parse_world
from grove_tui.tui.widgets import map_raster as mr

WORLD = TWO_ROOMS


@pytest.fixture(scope="module")
def world():
    built, problems = parse_world(WORLD)
    assert built is not None, problems
    return built


@pytest.fixture(scope="module")
def raster(world):
    return mr.MapRaster(world, 2.0)  # 2 columns (4 dots) per metre


def text_of(chars: np.ndarray) -> list[str]:
    return [mr.row_text(row) for row in chars]


def test_walls_are_braille_with_door_gaps_and_labels(raster):
    rows = text_of(raster.base_chars)
    assert all(len(r) == raster.width for r in rows)
    braille = np.count_nonzero((raster.base_chars >= 0x2801) & (raster.base_chars <= 0x28FF))
    assert braille > 100
    assert any("hall" in r for r in rows) and any("shop" in r for r in rows)
    door_rows, door_cols = np.nonzero(raster.base_chars == ord("▒"))
    assert len(door_rows) == 2
    assert set(raster.base_styles[door_rows, door_cols]) == {mr.DOOR}
    # the entrance opening (x 9.2..10.8 on y=0) has no wall dots in its middle
    row, col = raster.to_cells(np.array([[9.6, 0.0]]))
    assert raster.base_styles[row[0], col[0]] != mr.WALL


def test_fit_scale_fits_the_world_in_the_given_cells(world):
    scale = mr.MapRaster.fit_scale(world, 60, 20)
    fitted = mr.MapRaster(world, scale)
    assert fitted.width <= 61 and fitted.height <= 21


def test_overlays_mark_spawns_goals_waypoints_robot_path_and_highlight(raster):
    overlay = mr.Overlay(spawns=np.array([[2.0, 2.0]]), goals=np.array([[25.0, 5.0]]),
                         waypoints=np.array([[15.0, 5.0]]), robot_path=np.array([[1.0, 8.0], [18.0, 8.0]]),
                         highlight_path=np.array([[2.0, 2.0], [15.0, 5.0], [25.0, 5.0]]),
                         highlight_points=np.array([[2.0, 2.0]]))
    chars, styles = raster.compose(overlay)
    for point, glyph in (([25.0, 5.0], "◎"), ([15.0, 5.0], "·"), ([2.0, 2.0], "◆")):
        row, col = raster.to_cells(np.array([point]))
        assert chr(chars[row[0], col[0]]) == glyph
    assert np.count_nonzero(styles == mr.ROBOT_PATH) > 10
    assert np.count_nonzero(styles == mr.HIGHLIGHT) > 10
    assert (raster.base_chars == raster.compose(None)[0]).all()


@dataclass
class Field:
    origin: tuple[float, float]
    resolution: float
    vectors: np.ndarray


def test_velocity_field_draws_arrows_in_its_direction(raster):
    vectors = np.zeros((100, 300, 2), dtype=np.float32)
    vectors[..., 0] = 1.0  # everything flows to +x
    chars, styles = raster.compose(mr.Overlay(fields=(Field((0.0, 0.0), 0.1, vectors),)))
    arrows = chars[styles == mr.FIELD]
    assert len(arrows) > 20
    assert set(map(chr, arrows)) == {"→"}


def test_agents_are_dot_blobs_coloured_by_group_and_the_selected_one_stands_out(raster):
    positions = np.array([[3.0, 3.0], [12.0, 3.0], [24.0, 7.0]])
    cells = mr.rasterise_agents(raster, positions, np.array([0, 1, 1]), selected=2, robot=(10.0, 8.0, np.pi / 2))
    by_cell = {(int(r), int(c)): (chr(ch), int(st)) for r, c, ch, st in zip(cells.rows, cells.cols, cells.chars, cells.styles)}
    row, col = raster.to_cells(positions)
    assert by_cell[(row[0], col[0])][1] == mr.GROUP_BASE + 0
    assert by_cell[(row[1], col[1])][1] == mr.GROUP_BASE + 1
    assert by_cell[(row[2], col[2])][1] == mr.SELECTED
    assert all(0x2801 <= ord(by_cell[(row[i], col[i])][0]) <= 0x28FF for i in range(3))
    rrow, rcol = raster.to_cells(np.array([[10.0, 8.0]]))
    assert by_cell[(rrow[0], rcol[0])] == ("↑", mr.ROBOT)
    assert set(cells.by_row()) == set(int(r) for r in cells.rows)


def test_agents_outside_the_map_are_dropped(raster):
    cells = mr.rasterise_agents(raster, np.array([[-50.0, -50.0], [500.0, 3.0]]), np.array([0, 0]))
    assert len(cells.rows) == 0


def test_row_runs_split_a_row_by_style():
    assert mr.row_runs(np.array([0, 0, 1, 1, 1, 0], dtype=np.uint8)) == [(0, 2, 0), (2, 5, 1), (5, 6, 0)]


def test_markers_on_a_zone_label_move_the_label_instead_of_cutting_it(raster):
    base_rows = text_of(raster.base_chars)
    label_row = next(i for i, row in enumerate(base_rows) if "hall" in row)
    col = base_rows[label_row].index("hall")
    # a row of spawn markers right across the label, where the issue saw "○p○○◆○○"
    points = np.array([raster.cell_centre(label_row, c) for c in range(col - 2, col + 6)])
    chars, _styles = raster.compose(mr.Overlay(spawns=points))
    rows = text_of(chars)
    assert "○" * 8 in rows[label_row], "the markers themselves must stay"
    assert any("hall" in row for row in rows), "the label was cut by the markers"
