"""At 80x24 (an SSH session's default) every screen's footer still shows how to quit and how to get help."""

from __future__ import annotations

import pytest
from helpers.app import (
    fake_llm_session,
    test_settings,
    wait_until,
)
from helpers.app import PROMPT, setup_ready
from textual.widgets._footer import FooterKey

from grove_tui.tui.app import GroveApp
from grove_tui.tui.screens.inspect import InspectScreen
from grove_tui.tui.screens.simulation import SimulationScreen

pytestmark = pytest.mark.anyio

WIDTH, HEIGHT = 80, 24


async def visible_footer_actions(pilot) -> set[str]:
    """Footer keys that are drawn whole inside the terminal (once the footer has been laid out)."""
    screen = pilot.app.screen
    await wait_until(pilot, lambda: any(key.region.width > 0 for key in screen.query(FooterKey)), what="footer")
    await pilot.pause()
    keys = list(screen.query(FooterKey))
    # the command palette key, when shown, is docked over the right end of the footer
    edge = min([WIDTH] + [key.region.x for key in keys if key.action == "command_palette"])
    return {key.action for key in keys if key.action != "command_palette" and 0 < key.region.width
            and key.region.right <= edge}


@pytest.mark.slow
async def test_quit_and_help_stay_visible_on_every_screen_at_80x24(tmp_path):
    app = GroveApp(fake_llm_session(tmp_path / "runs"), test_settings(tmp_path))
    async with app.run_test(size=(WIDTH, HEIGHT)) as pilot:
        await setup_ready(pilot)
        seen = {"setup": await visible_footer_actions(pilot)}
        await pilot.press(*PROMPT, "enter")
        await wait_until(pilot, lambda: isinstance(app.screen, InspectScreen), timeout=60, what="inspect")
        seen["inspect"] = await visible_footer_actions(pilot)
        await pilot.press("p")
        await wait_until(pilot, lambda: isinstance(app.screen, SimulationScreen), what="simulation")
        seen["simulation"] = await visible_footer_actions(pilot)
        for screen, actions in seen.items():
            assert {"quit", "help"} <= actions, (screen, sorted(actions))
        # the screen's own way forward and back is on show too
        assert {"simulate", "back"} <= seen["inspect"]
        assert {"toggle_play", "export", "back"} <= seen["simulation"]
