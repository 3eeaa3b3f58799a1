"""Issue 21, responsiveness: what F1/Escape cost the UI thread and what the session's heap keeps.

Timings are in bench/tui_fps.py --key-latency; these tests check the mechanisms that keep them low:
the help page is rendered once per screen and width, closed screens leave nothing reachable that
every garbage collection must walk again, and the long-lived heap is frozen after the warm-up.
"""

from __future__ import annotations

import gc

import pytest
from helpers.app import FIXED_SCRIPT, ScriptedSession, fake_llm_session, setup_ready, test_settings, wait_until
from textual._styles_cache import StylesCache
from textual.widget import Widget
from textual.widgets import Static
from textual.widgets._footer import FooterKey

from grove_tui.settings import UISettings
from grove_tui.tui.app import GroveApp
from grove_tui.tui.screens.help import HelpPage, HelpScreen
from grove_tui.tui.screens.setup import SetupScreen
from grove_tui.tui.widgets.footer import Footer

pytestmark = pytest.mark.anyio


async def open_and_close_help(pilot, app: GroveApp, times: int) -> None:
    for _ in range(times):
        await pilot.press("f1")
        await wait_until(pilot, lambda: isinstance(app.screen, HelpScreen), what="help")
        await pilot.press("escape")
        await wait_until(pilot, lambda: isinstance(app.screen, SetupScreen), what="setup again")


@pytest.mark.slow
async def test_the_footer_keeps_only_the_keys_it_shows(tmp_path):
    app = GroveApp(ScriptedSession(FIXED_SCRIPT), test_settings(tmp_path))
    async with app.run_test(size=(80, 24)) as pilot:
        await setup_ready(pilot)
        await open_and_close_help(pilot, app, 5)
        await pilot.pause(0.2)
        footer = app.screen.query_one(Footer)
        shown = list(footer.query(FooterKey))
        watched = [node for node, _ in getattr(footer, "__watchers", {}).get("compact", [])]
        # Textual's own footer kept every removed key here (about 20 per F1/Escape) for the whole session.
        assert len(watched) == len(shown) and set(map(id, watched)) == set(map(id, shown))


@pytest.mark.slow
async def test_closed_screens_leave_no_render_caches_behind(tmp_path):
    app = GroveApp(ScriptedSession(FIXED_SCRIPT), test_settings(tmp_path))
    async with app.run_test(size=(80, 24)) as pilot:
        await setup_ready(pilot)
        await open_and_close_help(pilot, app, 5)
        await pilot.pause(0.2)
        widgets = sum(1 for node in app.screen.walk_children(with_self=True) if isinstance(node, Widget))
        # One memo entry per painted widget (and a background or two), not the ~20 of every help page closed.
        assert StylesCache.get_inner_outer.cache_info().currsize <= 2 * widgets


@pytest.mark.slow
async def test_help_is_rendered_once_per_screen_and_width(tmp_path):
    app = GroveApp(ScriptedSession(FIXED_SCRIPT), test_settings(tmp_path))
    async with app.run_test(size=(80, 24)) as pilot:
        await setup_ready(pilot)
        pages = []
        for _ in range(2):
            await pilot.press("f1")
            await wait_until(pilot, lambda: isinstance(app.screen, HelpScreen), what="help")
            page = app.screen.query_one(HelpPage)
            await wait_until(pilot, lambda p=page: bool(p._strips), what="help painted")
            pages.append(page._strips)
            await pilot.press("escape")
            await wait_until(pilot, lambda: isinstance(app.screen, SetupScreen), what="setup again")
        assert pages[0] is pages[1], "the second F1 rendered the same page again"
        assert any("setup.generate" in strip.text for strip in pages[0])


async def test_the_heap_is_frozen_once_the_warm_up_is_done(tmp_path):
    settings = test_settings(tmp_path).model_copy(update={"ui": UISettings(preload_models=True)})
    app = GroveApp(fake_llm_session(tmp_path / "runs"), settings)
    try:
        async with app.run_test(size=(80, 24)) as pilot:
            await wait_until(pilot, lambda: isinstance(app.screen, SetupScreen), what="setup")
            models = app.screen.query_one("#models", Static)
            await wait_until(pilot, lambda: "ready to generate" in str(models.render()), timeout=60, what="ready")
            frozen = app.frozen_heap
            assert frozen is not None, "the warm-up ended without freezing the heap"
            # The app's modules, the world and the reader: far more than the UI creates afterwards.
            assert frozen.frozen > 100_000 and gc.get_freeze_count() > 100_000
            assert len(gc.get_objects()) < frozen.frozen / 4, "a full collection still walks most of the heap"
    finally:
        gc.unfreeze()  # the rest of the test session collects as usual
