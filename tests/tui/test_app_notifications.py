"""Issue 21 item 10: notifications belong to the screen they were raised on."""

from __future__ import annotations

import pytest
from helpers.app import first_frame, generate_to_inspect
from helpers.app import (
    FIXED_SCRIPT,
    ScriptedSession,
    fake_llm_session,
    test_settings,
    wait_until,
)

from grove_tui.tui.app import GroveApp
from grove_tui.tui.screens.generation import GenerationScreen
from grove_tui.tui.screens.recent import RecentRunsScreen
from grove_tui.tui.screens.setup import SetupScreen
from grove_tui.tui.screens.simulation import SimulationScreen

pytestmark = pytest.mark.anyio


def messages(app: GroveApp) -> list[str]:
    return [str(n.message) for n in app._notifications]


@pytest.mark.slow
async def test_notifications_are_cleared_when_the_screen_changes_but_not_for_a_dialog(tmp_path):
    app = GroveApp(fake_llm_session(tmp_path / "runs"), test_settings(tmp_path))
    async with app.run_test(size=(80, 24)) as pilot:
        inspect = await generate_to_inspect(pilot, app)
        app.notify("about the inspect screen", timeout=60)
        await pilot.press("c")  # a dialog over the same screen keeps it
        await wait_until(pilot, lambda: app.screen is not inspect, what="counts dialog")
        assert "about the inspect screen" in messages(app)
        await pilot.press("escape")
        await wait_until(pilot, lambda: app.screen is inspect, what="inspect")
        await pilot.press("p")
        await wait_until(pilot, lambda: isinstance(app.screen, SimulationScreen), what="simulation")
        assert "about the inspect screen" not in messages(app)
        sim = app.screen
        await first_frame(pilot, sim)
        await pilot.press("c")  # "colour by behavior"
        assert any("colour by" in m for m in messages(app))
        await pilot.press("escape")
        await wait_until(pilot, lambda: app.screen is inspect, what="back to inspect")
        assert not any("colour by" in m for m in messages(app))


@pytest.mark.slow
async def test_a_notification_raised_after_the_switch_stays(tmp_path):
    app = GroveApp(ScriptedSession(FIXED_SCRIPT, outcome="block", block_seconds=20), test_settings(tmp_path))
    async with app.run_test(size=(80, 24)) as pilot:
        await wait_until(pilot, lambda: isinstance(app.screen, SetupScreen), what="setup")
        await pilot.press("enter")  # no prompt: a warning on setup
        assert any("Type a prompt first" in m for m in messages(app))
        await pilot.press("ctrl+o")
        await wait_until(pilot, lambda: isinstance(app.screen, RecentRunsScreen), what="recent runs")
        assert any("Type a prompt first" in m for m in messages(app)), "a dialog cleared the setup's warning"
        await pilot.press("escape")
        await wait_until(pilot, lambda: isinstance(app.screen, SetupScreen), what="setup")
        await wait_until(pilot, lambda: app.screen.selected_world is not None and app.screen.selected_preset is not None,
                         what="catalogue")
        await pilot.press(*"six patients queue", "enter")
        await wait_until(pilot, lambda: isinstance(app.screen, GenerationScreen), what="generation")
        assert not any("Type a prompt first" in m for m in messages(app))
        await pilot.press("escape")
        await wait_until(pilot, lambda: isinstance(app.screen, SetupScreen), what="cancelled")
        await pilot.pause(0.1)
        assert "Generation cancelled." in messages(app)
