"""Pilot tests of editing head counts on the inspect screen: re-planned without the model, errors in place."""

from __future__ import annotations

import pytest
from helpers.app import CLEAR, generate_to_inspect, open_counts
from helpers.app import (
    FakeLLM,
    fake_llm_session,
    test_settings,
    wait_until,
)
from textual.widgets import Input, Static

from grove_tui.tui.app import GroveApp
from grove_tui.tui.screens.counts import CountsScreen
from grove_tui.tui.screens.help import HelpScreen
from grove_tui.tui.screens.inspect import InspectScreen
from grove_tui.tui.widgets.bt_tree import BTTree

pytestmark = pytest.mark.anyio

@pytest.mark.slow
async def test_edit_a_count_and_replan_without_the_model(tmp_path):
    llm = FakeLLM()
    app = GroveApp(fake_llm_session(tmp_path / "runs", llm), test_settings(tmp_path))
    async with app.run_test(size=(80, 24)) as pilot:
        inspect = await generate_to_inspect(pilot, app)
        first = inspect.generated
        assert len(first.scenario.agents) == 6
        requests = llm.requests

        dialog = await open_counts(pilot, app)
        field = dialog.query_one("#count-0", Input)
        assert field.value == "6" and app.focused is field
        assert "patient" in str(dialog.query_one(".counts-label", Static).render())
        await pilot.press(*CLEAR, *"x9", "enter")  # letters are refused: digits only
        await wait_until(pilot, lambda: isinstance(app.screen, InspectScreen), timeout=60, what="back to inspect")
        assert app.screen is inspect
        await wait_until(pilot, lambda: inspect.generated is not first, what="new scenario shown")

        assert llm.requests == requests, "re-planning called the model"
        generated = inspect.generated
        assert app.generated is generated
        assert len(generated.scenario.agents) == 9
        assert [a.id for a in generated.scenario.agents] == list(range(1, 10))
        assert generated.result.report["notes"][0] == "counts edited: patient 6 -> 9"
        assert generated.bundle_dir != first.bundle_dir and (generated.bundle_dir / "scenario.yaml").is_file()
        assert len(first.scenario.agents) == 6  # the first scenario and its bundle are untouched

        tree = inspect.query_one("#bt-tree", BTTree)
        await wait_until(pilot, lambda: bool(tree.root.children), what="trees rebuilt")
        assert "×9" in str(tree.root.children[0].label)
        assert "9 agents" in str(tree.border_title)
        assert len(tree.agent_nodes) == 9
        assert len(inspect._overlay.spawns) == 9  # the map shows the new spawns
        await wait_until(pilot, lambda: inspect._selected_node is not None, what="first agent selected")

        # the counts dialog now starts from the new numbers; Escape keeps the scenario
        dialog = await open_counts(pilot, app)
        assert dialog.query_one("#count-0", Input).value == "9"
        await pilot.press("escape")
        await wait_until(pilot, lambda: app.screen is inspect, what="dialog closed")
        assert inspect.generated is generated


@pytest.mark.slow
async def test_impossible_counts_show_the_error_in_the_dialog(tmp_path):
    app = GroveApp(fake_llm_session(tmp_path / "runs"), test_settings(tmp_path))
    async with app.run_test(size=(80, 24)) as pilot:
        inspect = await generate_to_inspect(pilot, app)
        first = inspect.generated
        dialog = await open_counts(pilot, app)
        error = dialog.query_one("#counts-error", Static)
        assert not error.display

        # an empty count is refused before any re-planning
        await pilot.press(*CLEAR, "enter")
        assert error.display and "has no count" in str(error.render())

        # more people than the preset allows in one group: the engine's message and what to do
        await pilot.press(*"99", "enter")
        await wait_until(pilot, lambda: "out of range" in str(error.render()), timeout=60, what="error shown")
        text = str(error.render())
        assert "99 people" in text and "1 to 40" in text and "→" in text
        assert isinstance(app.screen, CountsScreen) and not dialog.replanning
        assert not dialog.query_one("#count-0", Input).disabled

        # the F1 help of the dialog is there, and lists its keys
        await pilot.press("f1")
        await wait_until(pilot, lambda: isinstance(app.screen, HelpScreen), what="help")
        await pilot.press("escape")
        await wait_until(pilot, lambda: app.screen is dialog, what="back to the dialog")

        await pilot.press("escape")
        await wait_until(pilot, lambda: app.screen is inspect, what="dialog closed")
        assert inspect.generated is first and len(first.scenario.agents) == 6


@pytest.mark.slow
async def test_inspect_help_lists_the_counts_binding(tmp_path):
    app = GroveApp(fake_llm_session(tmp_path / "runs"), test_settings(tmp_path))
    async with app.run_test(size=(80, 24)) as pilot:
        await generate_to_inspect(pilot, app)
        await pilot.press("f1")
        await wait_until(pilot, lambda: isinstance(app.screen, HelpScreen), what="help")
        from grove_tui.tui.screens.help import keys_table

        table = keys_table(app.screen._screen)
        assert "| `c` | Counts | `inspect.counts` |" in table
