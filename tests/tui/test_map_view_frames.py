"""The live map's frames (issue 21, 500 agents at 15 fps): only rows whose agents changed are repainted,
and what a row shows after many frames is what a fresh map shows for the last frame alone."""

from __future__ import annotations

import numpy as np
import pytest
from textual.app import App, ComposeResult
from textual.containers import Horizontal

from grove_tui.tui.widgets import map_raster as mr
from grove_tui.tui.widgets.map_view import MapView
from helpers.two_rooms import TWO_ROOMS

from grove_tui.world import parse_world

pytestmark = pytest.mark.anyio

WORLD = TWO_ROOMS


class TwoMaps(App[None]):
    """One map that plays every frame, one that is only ever given the last frame."""

    def compose(self) -> ComposeResult:
        with Horizontal():
            yield MapView(id="playing")
            yield MapView(id="fresh")


def rendered(world_map: MapView) -> list[list[tuple[str, object]]]:
    return [[(segment.text, segment.style) for segment in world_map.render_line(y)]
            for y in range(world_map.size.height)]


def frame(world_map: MapView, positions: np.ndarray, selected: int = -1) -> mr.AgentCells:
    assert world_map.raster is not None
    return mr.rasterise_agents(world_map.raster, positions, np.arange(len(positions)) % 3, selected,
                               robot=(15.0, 2.0, 0.5))


async def test_only_changed_rows_repaint_and_rows_match_a_fresh_map():
    built, problems = parse_world(WORLD)
    assert built is not None, problems
    app = TwoMaps()
    async with app.run_test(size=(80, 20)) as pilot:
        playing = app.query_one("#playing", MapView)
        fresh = app.query_one("#fresh", MapView)
        for world_map in (playing, fresh):
            world_map.set_world(built)
        await pilot.pause()
        assert playing.raster is not None and playing.raster.height <= playing.size.height
        rng = np.random.default_rng(3)
        positions = np.column_stack([rng.uniform(1, 29, 40), rng.uniform(1, 9, 40)])
        first = frame(playing, positions)
        assert playing.set_agents(first) == len(first.by_row())  # every row with agents is new
        rendered(playing)
        assert playing.set_agents(frame(playing, positions)) == 0  # nothing moved: nothing repainted
        # One agent jumps to other rows: the rows it left and the rows it reached (a blob may span two), no others.
        moved = positions.copy()
        moved[0] = (positions[0, 0], positions[0, 1] + 4.0 if positions[0, 1] < 5 else positions[0, 1] - 4.0)
        before, after = frame(playing, positions).by_row(), frame(playing, moved).by_row()
        changed = {row for row in before.keys() | after.keys()
                   if [a.tobytes() for a in before.get(row, ())] != [a.tobytes() for a in after.get(row, ())]}
        assert 2 <= len(changed) <= 4
        assert playing.set_agents(frame(playing, moved)) == len(changed)
        # Many frames later (walking, a selection, the robot), every row equals a map given only the last frame.
        for step in range(30):
            moved = np.clip(moved + rng.normal(0, 0.4, moved.shape), 0.5, [29.5, 9.5])
            playing.set_agents(frame(playing, moved, selected=step % 5))
            rendered(playing)  # each frame is drawn, as the compositor would
        fresh.set_agents(frame(fresh, moved, selected=29 % 5))
        await pilot.pause()
        assert rendered(playing) == rendered(fresh)
        # Leaving the map empty clears every row that had agents.
        playing.set_agents(None)
        fresh.set_agents(None)
        assert rendered(playing) == rendered(fresh)


def cells_as_seen(world_map: MapView) -> list[list[tuple]]:
    """What a terminal shows in each cell: the character and background, and the ink only where there is some."""
    rows = []
    for y in range(world_map.size.height):
        row = []
        for segment in world_map.render_line(y):
            style = segment.style
            for char in segment.text:
                blank = char in (" ", chr(mr.BLANK_BRAILLE))
                ink = None if blank else (style.color, style.bold, style.italic, style.dim)
                row.append((char, style.bgcolor, style.underline, style.reverse, ink))
        rows.append(row)
    return rows


async def test_blank_cells_joining_the_run_before_them_change_nothing_on_screen(monkeypatch):
    built, problems = parse_world(WORLD)
    assert built is not None, problems
    app = TwoMaps()
    async with app.run_test(size=(80, 20)) as pilot:
        merged = app.query_one("#playing", MapView)
        plain = app.query_one("#fresh", MapView)
        for world_map in (merged, plain):
            world_map.set_world(built)
        await pilot.pause()
        rng = np.random.default_rng(5)
        positions = np.column_stack([rng.uniform(1, 29, 60), rng.uniform(1, 9, 60)])
        for world_map in (merged, plain):
            world_map.set_agents(frame(world_map, positions, selected=4))  # the selection has a background
        merged_cells, merged_segments = cells_as_seen(merged), sum(len(list(merged.render_line(y)))
                                                                   for y in range(merged.size.height))
        monkeypatch.setattr(mr, "merge_blank_cells", lambda chars, styles, safe: styles)
        plain._strip_cache.clear()
        plain._agent_strips.clear()
        plain_cells, plain_segments = cells_as_seen(plain), sum(len(list(plain.render_line(y)))
                                                                for y in range(plain.size.height))
        assert merged_cells == plain_cells
        assert merged_segments < 0.8 * plain_segments, (merged_segments, plain_segments)


def test_a_blank_cell_takes_the_style_before_it_only_where_both_look_alike():
    space, dots, empty = ord(" "), mr.BRAILLE_BASE + 0x09, mr.BLANK_BRAILLE
    safe = np.array([True, True, False])  # style 2 paints a background (the selection)
    chars = np.array([space, dots, space, empty, dots, space, dots, space, space], dtype=np.uint32)
    styles = np.array([0, 1, 0, 0, 2, 0, 1, 2, 0], dtype=np.uint8)
    merged = mr.merge_blank_cells(chars, styles, safe)
    # a leading blank keeps its style; blanks after a safe cell join it; after the selection they do not;
    # a blank in a background style is not blank-safe itself and stays
    assert merged.tolist() == [0, 1, 1, 1, 2, 0, 1, 2, 0]
