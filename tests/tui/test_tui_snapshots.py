"""SVG snapshots of every screen at 80x24 and 120x40 (pytest-textual-snapshot).

Deterministic by construction: fixed seed, a fake LLM with a fixed answer, scripted pipeline timings,
simulated time only (no wall clock), cursor blink off. Accept intended changes with
`python -m pytest -n 0 tests/tui/test_tui_snapshots.py --snapshot-update` and review the SVGs.
"""

from __future__ import annotations

import pytest
from helpers.app import (
    FIXED_SCRIPT,
    PROMPT,
    ScriptedSession,
    fake_llm_session,
    setup_ready,
    test_settings,
    wait_until,
)
from textual.widgets import DataTable, Static

from grove_tui.services.session import ScenarioRequest
from grove_tui.tui.app import GroveApp
from grove_tui.tui.screens.generation import GenerationScreen
from grove_tui.tui.screens.help import HelpScreen
from grove_tui.tui.screens.inspect import InspectScreen
from grove_tui.tui.screens.recent import RecentRunsScreen
from grove_tui.tui.screens.simulation import SimulationScreen
from grove_tui.tui.widgets.bt_tree import BTTree

SIZES = [pytest.param((80, 24), id="80x24"), pytest.param((120, 40), id="120x40")]


async def to_inspect(pilot) -> InspectScreen:
    await setup_ready(pilot)
    await pilot.press(*PROMPT, "enter")
    app = pilot.app
    await wait_until(pilot, lambda: isinstance(app.screen, InspectScreen), timeout=60, what="inspect")
    screen = app.screen
    await wait_until(pilot, lambda: screen._selected_node is not None, what="first agent selected")
    return screen


class TestSetupScreen:
    @pytest.mark.parametrize("size", SIZES)
    def test_setup(self, snap_compare, tmp_path, size):
        app = GroveApp(ScriptedSession(FIXED_SCRIPT), test_settings(tmp_path))
        assert snap_compare(app, terminal_size=size, run_before=setup_ready)


class TestGenerationScreen:
    @pytest.mark.slow
    @pytest.mark.parametrize("size", SIZES)
    def test_generation_streaming(self, snap_compare, tmp_path, size, monkeypatch):
        from grove_tui.tui.screens import generation

        # A stopped progress clock: elapsed 0.0 s and a fixed rate, whatever the machine's speed.
        monkeypatch.setattr(generation, "monotonic", lambda: 100.0)
        session = ScriptedSession(FIXED_SCRIPT, outcome="block", block_seconds=10)

        async def run_before(pilot) -> None:
            await setup_ready(pilot)
            await pilot.press(*PROMPT, "enter")
            app = pilot.app
            await wait_until(pilot, lambda: isinstance(app.screen, GenerationScreen), what="generation")
            screen = app.screen
            await wait_until(pilot, session.blocking.is_set, what="script played")
            table = screen.query_one("#stages", DataTable)
            await wait_until(pilot, lambda: table.get_cell("synthesis", "state") == "running", what="synthesis")
            await wait_until(pilot, lambda: "patients" in str(screen.query_one("#stream", Static).render()),
                             what="stream")
            await wait_until(pilot, lambda: "tok/s" in str(table.get_cell("synthesis", "detail")), what="progress")
            # The Detail column widens on the table's next layout pass, not when the cell changes: under
            # load the snapshot could be taken in between, with "1000.0 tok/s" cut to the old width.
            detail_width = len(str(table.get_cell("synthesis", "detail")))
            await wait_until(pilot, lambda: table.columns["detail"].get_render_width(table) >= detail_width
                             and table.virtual_size.width >= sum(c.get_render_width(table) for c in table.columns.values()),
                             what="the table laid out for its widest detail")
            await pilot.pause()

        app = GroveApp(session, test_settings(tmp_path))
        assert snap_compare(app, terminal_size=size, run_before=run_before)


class TestInspectScreen:
    @pytest.mark.slow
    @pytest.mark.parametrize("size", SIZES)
    def test_inspect(self, snap_compare, tmp_path, size):
        app = GroveApp(fake_llm_session(tmp_path / "runs"), test_settings(tmp_path))
        assert snap_compare(app, terminal_size=size, run_before=to_inspect)


class TestInspectGrounding:
    """The grounding report (key `a`) beside the map, read from the generated bundle's report."""

    @pytest.mark.slow
    def test_grounding_report_at_80x24(self, snap_compare, tmp_path):
        async def run_before(pilot) -> None:
            screen = await to_inspect(pilot)
            await pilot.press("a")
            await wait_until(pilot, lambda: screen.query_one("#grounding").display, what="grounding panel")
            await pilot.pause()

        app = GroveApp(fake_llm_session(tmp_path / "runs"), test_settings(tmp_path))
        assert snap_compare(app, terminal_size=(80, 24), run_before=run_before)


# The first steps of a fresh checkout compile the crowd's numba kernels (no on-disk cache yet): over
# three minutes at load 11 on 2 cores. The waits end as soon as the frames are there.
FIRST_STEPS_SECONDS = 400


class TestSimulationScreen:
    @pytest.mark.slow
    @pytest.mark.parametrize("size", SIZES)
    def test_simulation_after_ten_steps(self, snap_compare, tmp_path, size):
        async def run_before(pilot) -> None:
            await to_inspect(pilot)
            await pilot.press("p")
            app = pilot.app
            await wait_until(pilot, lambda: isinstance(app.screen, SimulationScreen), what="simulation")
            sim = app.screen
            await wait_until(pilot, lambda: sim.controller is not None and sim.controller.latest is not None,
                             timeout=FIRST_STEPS_SECONDS, what="first frame")
            await pilot.press(*["n"] * 10)
            await wait_until(pilot, lambda: sim.controller.latest.frame.step == 10, timeout=FIRST_STEPS_SECONDS,
                             what="ten steps")
            tree = sim.query_one("#sim-tree", BTTree)
            await wait_until(pilot, lambda: sim._shown_serial == sim.controller.latest.serial and bool(tree._status),
                             what="last frame drawn")
            await wait_until(pilot, lambda: sim.metrics_step == sim.controller.latest.frame.step,
                             what="counters of the last frame")

        app = GroveApp(fake_llm_session(tmp_path / "runs"), test_settings(tmp_path))
        assert snap_compare(app, terminal_size=size, run_before=run_before)


class TestHelpScreen:
    @pytest.mark.slow
    @pytest.mark.parametrize("size", SIZES)
    def test_help_for_the_prompt(self, snap_compare, tmp_path, size):
        async def run_before(pilot) -> None:
            await setup_ready(pilot)
            await pilot.press("f1")
            await wait_until(pilot, lambda: isinstance(pilot.app.screen, HelpScreen), what="help")

        app = GroveApp(ScriptedSession(FIXED_SCRIPT), test_settings(tmp_path))
        assert snap_compare(app, terminal_size=size, run_before=run_before)


class TestRecentRunsScreen:
    @pytest.mark.slow
    def test_recent_runs(self, snap_compare, tmp_path, monkeypatch):
        import os
        import time

        # Fixed home, clock zone and file times: the list shows the folder (as ~/...) and each run's time.
        monkeypatch.setenv("HOME", str(tmp_path))
        monkeypatch.setenv("TZ", "UTC")
        time.tzset()
        session = fake_llm_session(tmp_path / "runs")
        for index, seed in enumerate((3, 4)):
            generated = session.generate(ScenarioRequest("hospital", "queuing", PROMPT, seed), show_loading=True)
            stamp = 1_790_000_000 + 600 * index
            os.utime(generated.bundle_dir / "scenario.yaml", (stamp, stamp))

        async def run_before(pilot) -> None:
            await setup_ready(pilot)
            await pilot.press("ctrl+o")
            app = pilot.app
            await wait_until(pilot, lambda: isinstance(app.screen, RecentRunsScreen) and len(app.screen.runs) == 2,
                             what="recent runs")

        app = GroveApp(session, test_settings(tmp_path))
        try:
            assert snap_compare(app, terminal_size=(80, 24), run_before=run_before)
        finally:
            monkeypatch.undo()
            time.tzset()
