"""Issue 21 item 8: long text at 80x24 wraps or scrolls sideways, never just ends mid-word."""

from __future__ import annotations

import pytest
from helpers.app import generate_to_inspect
from helpers.app import (
    ScriptedSession,
    StageFinished,
    StageStarted,
    fake_llm_session,
    test_settings,
    wait_until,
)
from textual.widgets import DataTable, Static, TextArea

from grove_tui.tui.app import GroveApp
from grove_tui.tui.screens.generation import GenerationScreen
from grove_tui.tui.screens.setup import SetupScreen
from grove_tui.tui.widgets.bt_tree import BTTree

pytestmark = pytest.mark.anyio

LONG_DETAIL = "pharmacy, pharmacy_counter, main_entrance, waiting_area, cafeteria, radiology_desk (6 places)"


@pytest.mark.slow
async def test_a_long_stage_detail_scrolls_into_view(tmp_path):
    script = [StageStarted("rois"), StageFinished("rois", 0.4, 300, 12, LONG_DETAIL), StageStarted("retrieval")]
    app = GroveApp(ScriptedSession(script, outcome="block", block_seconds=20), test_settings(tmp_path))
    async with app.run_test(size=(80, 24)) as pilot:
        await wait_until(pilot, lambda: isinstance(app.screen, SetupScreen), what="setup")
        await wait_until(pilot, lambda: app.screen.selected_world is not None and app.screen.selected_preset is not None,
                         what="catalogue")
        await pilot.press(*"six patients queue", "enter")
        await wait_until(pilot, lambda: isinstance(app.screen, GenerationScreen), what="generation")
        table = app.screen.query_one("#stages", DataTable)
        await wait_until(pilot, lambda: str(table.get_cell("rois", "detail")) == LONG_DETAIL, what="detail")
        await pilot.pause(0.1)
        assert table.max_scroll_x > 0, "the detail fits: this test needs a longer one"
        assert app.focused is table
        for _ in range(table.max_scroll_x):
            await pilot.press("right")
        await wait_until(pilot, lambda: table.scroll_x == table.max_scroll_x, what="scrolled to the end")
        await pilot.press("escape")


@pytest.mark.slow
async def test_inspect_wraps_the_xml_and_shows_every_port_of_a_node(tmp_path):
    app = GroveApp(fake_llm_session(tmp_path / "runs"), test_settings(tmp_path))
    async with app.run_test(size=(80, 24)) as pilot:
        inspect = await generate_to_inspect(pilot, app)
        tree = inspect.query_one("#bt-tree", BTTree)
        await wait_until(pilot, lambda: inspect._selected_node is not None, what="agent selected")
        await pilot.press("down", "down")  # the agent's GoTo node, whose ports run past 34 columns
        await wait_until(pilot, lambda: inspect._selected_node.kind == "node", what="a node")
        detail = inspect.query_one("#node-detail", Static)
        await pilot.pause(0.1)
        ports = inspect._selected_node.ports
        shown = str(detail.render())
        assert all(f"{key} = {value}" in shown for key, value in ports.items())
        assert detail.virtual_size.height <= detail.size.height or detail.max_scroll_y > 0
        # tree lines longer than the panel scroll sideways
        assert tree.max_scroll_x > 0
        await pilot.press("right", "right")
        assert tree.scroll_x > 0
        await pilot.press("x")
        xml = inspect.query_one("#xml", TextArea)
        assert xml.display and xml.soft_wrap
        await pilot.pause(0.1)
        assert xml.max_scroll_x == 0, "the XML runs past the panel"
