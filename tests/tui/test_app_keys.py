"""Keyboard-only use: command palette entries, map zoom and pan, binding ids, breakpoints."""

from __future__ import annotations

import pytest
from helpers.app import (
    FIXED_SCRIPT,
    ScriptedSession,
    fake_llm_session,
    map_laid_out,
    test_settings,
    wait_until,
)
from textual.command import CommandPalette

from grove_tui.tui.app import GroveApp
from grove_tui.tui.screens.inspect import InspectScreen
from grove_tui.tui.screens.setup import SetupScreen
from grove_tui.tui.screens.simulation import SimulationScreen
from grove_tui.tui.widgets.bt_tree import BTTree
from grove_tui.tui.widgets.map_view import MapView

pytestmark = pytest.mark.anyio

SCREENS = (SetupScreen, InspectScreen, SimulationScreen)


def test_every_screen_binding_has_an_id_a_description_and_an_ssh_safe_key():
    from grove_tui.tui.screens.generation import GenerationScreen
    from grove_tui.tui.screens.simulation import SimMapView
    from grove_tui.tui.widgets.prompt_input import PromptInput

    safe_names = {"escape", "enter", "space", "up", "down", "left", "right", "plus", "minus", "equals_sign",
                  "left_square_bracket", "right_square_bracket", "f1", "f2"}
    ids = []
    for owner in (GroveApp, GenerationScreen, MapView, SimMapView, PromptInput, *SCREENS):
        for binding in owner.BINDINGS:
            assert binding.id, f"{owner.__name__}: {binding.key} has no id"
            assert binding.description, f"{owner.__name__}: {binding.id} has no description"
            for key in binding.key.split(","):
                # alt+letter: readline's word keys, sent over SSH as ESC and the letter
                ok = (len(key) == 1 or key in safe_names or (key.startswith("ctrl+") and len(key) == 6)
                      or (key.startswith("alt+") and len(key) == 5))
                assert ok, f"{binding.id}: {key!r} may not reach the app over SSH"
            ids.append(binding.id)
    assert len(ids) == len(set(ids)), "binding ids must be unique so a keymap can address each"


async def inspect_ready(pilot, app: GroveApp) -> InspectScreen:
    await wait_until(pilot, lambda: isinstance(app.screen, SetupScreen), what="setup")
    await wait_until(pilot, lambda: app.screen.query_one("#preview", MapView).raster is not None, what="preview")
    await pilot.press(*"six patients queue at the pharmacy counter", "enter")
    await wait_until(pilot, lambda: isinstance(app.screen, InspectScreen), timeout=60, what="inspect")
    screen = app.screen
    await wait_until(pilot, lambda: bool(screen.query_one("#bt-tree", BTTree).root.children), what="trees")
    return screen


@pytest.mark.slow
async def test_command_palette_runs_the_screens_main_action(tmp_path):
    app = GroveApp(fake_llm_session(tmp_path / "runs"), test_settings(tmp_path))
    async with app.run_test(size=(100, 30)) as pilot:
        await inspect_ready(pilot, app)
        await pilot.press("ctrl+p")
        await wait_until(pilot, lambda: isinstance(app.screen, CommandPalette), what="palette")
        await pilot.press(*"play sim")
        await pilot.pause(0.3)
        await pilot.press("enter")
        await wait_until(pilot, lambda: isinstance(app.screen, SimulationScreen), what="simulation from the palette")


@pytest.mark.slow
async def test_map_zooms_pans_and_fits_with_keys(tmp_path):
    app = GroveApp(fake_llm_session(tmp_path / "runs"), test_settings(tmp_path))
    async with app.run_test(size=(80, 24)) as pilot:
        screen = await inspect_ready(pilot, app)
        await pilot.press("m")
        world_map = screen.query_one("#inspect-map", MapView)
        assert screen.focused is world_map
        await map_laid_out(pilot, world_map)
        fitted = (world_map.raster.width, world_map.raster.height)
        assert world_map.raster.width <= world_map.size.width
        await pilot.press("plus", "plus")
        zoomed = (world_map.raster.width, world_map.raster.height)
        assert zoomed[0] > fitted[0] * 2 and zoomed[1] > fitted[1] * 2
        await pilot.press("l", "l", "j")
        await pilot.pause()
        assert world_map.scroll_offset.x > 0 and world_map.scroll_offset.y > 0
        await pilot.press("0")
        assert (world_map.raster.width, world_map.raster.height) == fitted


async def test_narrow_terminals_fold_the_side_panels(tmp_path):
    app = GroveApp(ScriptedSession(FIXED_SCRIPT), test_settings(tmp_path))
    async with app.run_test(size=(80, 24)) as pilot:
        await wait_until(pilot, lambda: isinstance(app.screen, SetupScreen), what="setup")
        assert app.screen.has_class("-narrow")
        narrow = app.screen.query_one("#setup-side").size.width
    app = GroveApp(ScriptedSession(FIXED_SCRIPT), test_settings(tmp_path))
    async with app.run_test(size=(120, 40)) as pilot:
        await wait_until(pilot, lambda: isinstance(app.screen, SetupScreen), what="setup")
        assert app.screen.has_class("-wide")
        assert app.screen.query_one("#setup-side").size.width > narrow
