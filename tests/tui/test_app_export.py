"""Issue 21 item 4: export shows its progress, and the simulation pauses visibly while it runs."""

from __future__ import annotations

import threading

import pytest
from helpers.app import generate_to_inspect, generate_to_simulation
from helpers.app import (
    fake_llm_session,
    test_settings,
    wait_until,
)
from textual.widgets import ProgressBar, Static

from grove_tui.services.exporting import APP_EXPORTERS as EXPORTERS
from grove_tui.tui.app import GroveApp
from grove_tui.tui.screens.export import ExportProgressScreen, ExportResultScreen
from grove_tui.tui.screens.inspect import InspectScreen

pytestmark = pytest.mark.anyio


def gated_session(runs, gate: threading.Event, started: threading.Event):
    """The real exporters, with the picture held until the test has looked at the paused screen."""
    session = fake_llm_session(runs)

    def held_picture(ctx):
        started.set()
        gate.wait(60)
        dict(EXPORTERS)["picture"](ctx)

    session.exporters = [(kind, held_picture if kind == "picture" else exporter) for kind, exporter in EXPORTERS]
    return session


@pytest.mark.slow
async def test_export_while_playing_pauses_visibly_shows_progress_and_resumes(tmp_path):
    gate, started = threading.Event(), threading.Event()
    app = GroveApp(gated_session(tmp_path / "runs", gate, started), test_settings(tmp_path))
    async with app.run_test(size=(80, 24)) as pilot:
        sim = await generate_to_simulation(pilot, app)
        await pilot.press("space")
        await wait_until(pilot, lambda: sim.controller.latest.playing and sim.controller.latest.frame.t > 0.5,
                         what="playing")
        await pilot.press("e")
        await wait_until(pilot, lambda: isinstance(app.screen, ExportProgressScreen), what="progress dialog")
        dialog = app.screen
        await wait_until(pilot, started.is_set, timeout=60, what="export reached the picture")
        await wait_until(pilot, lambda: dialog.kind == "picture", what="progress shows the picture step")
        bar = dialog.query_one("#export-progress-bar", ProgressBar)
        kinds = [kind for kind, _ in EXPORTERS]
        assert bar.total == len(kinds) and bar.progress == kinds.index("picture")
        assert f"{kinds.index('picture') + 1}/{len(kinds)} · picture" in str(dialog.query_one("#export-progress-step",
                                                                                             Static).render())
        status = str(sim.query_one("#sim-status", Static).render())
        assert "paused for export" in status and "playing" not in status
        assert not sim.controller.playing
        t_paused = sim.controller.latest.frame.t
        await pilot.pause(0.5)
        assert sim.controller.latest.frame.t == t_paused, "the simulation went on unseen during the export"

        gate.set()
        await wait_until(pilot, lambda: isinstance(app.screen, ExportResultScreen), timeout=120, what="result")
        assert sim.controller.latest.frame.t == t_paused
        await pilot.press("escape")
        await wait_until(pilot, lambda: app.screen is sim, what="back to the simulation")
        await wait_until(pilot, lambda: sim.controller.latest.playing and sim.controller.latest.frame.t > t_paused,
                         what="playing again")
        assert "paused for export" not in str(sim.query_one("#sim-status", Static).render())


@pytest.mark.slow
async def test_export_from_inspect_shows_progress_then_the_files(tmp_path):
    gate, started = threading.Event(), threading.Event()
    app = GroveApp(gated_session(tmp_path / "runs", gate, started), test_settings(tmp_path))
    async with app.run_test(size=(80, 24)) as pilot:
        inspect = await generate_to_inspect(pilot, app)
        await pilot.press("e")
        await wait_until(pilot, lambda: isinstance(app.screen, ExportProgressScreen), what="progress dialog")
        await wait_until(pilot, lambda: app.screen.kind == "picture", timeout=60, what="picture step")
        gate.set()
        await wait_until(pilot, lambda: isinstance(app.screen, ExportResultScreen), timeout=60, what="result")
        await pilot.press("escape")
        await wait_until(pilot, lambda: app.screen is inspect and isinstance(inspect, InspectScreen), what="inspect")
