"""Issue 21 item 5: the simulation's counters are metrics.json's numbers, under metrics.json's names;
issue 31: they are measured as the run goes, each look reading only the frames since the last one."""

from __future__ import annotations

import json

import pytest
from helpers.app import generate_to_simulation
from helpers.app import (
    fake_llm_session,
    test_settings,
    wait_until,
)
from textual.widgets import Static

from grove_tui.tui.app import GroveApp
from grove_tui.tui.screens.export import ExportResultScreen
from grove_tui.tui.screens.simulation import LIVE_METRICS, metric_text

pytestmark = pytest.mark.anyio


@pytest.mark.slow
async def test_counters_shown_equal_the_exported_metrics_json_of_the_same_run(tmp_path):
    app = GroveApp(fake_llm_session(tmp_path / "runs"), test_settings(tmp_path))
    async with app.run_test(size=(120, 40)) as pilot:
        sim = await generate_to_simulation(pilot, app)
        await pilot.press("f", "space")  # as fast as possible: queues form, people get served, the run ends
        await wait_until(pilot, lambda: sim.controller.latest.ended is not None, timeout=120, what="the run's end")
        assert not sim.controller.latest.playing, "the run pauses itself at its end"
        paused_at = sim.controller.latest.frame.step
        await wait_until(pilot, lambda: sim.metrics_step == paused_at, timeout=30, what="counters of the paused run")
        counters = sim.query_one("#counters", Static)
        shown = str(counters.render())
        assert counters.border_title == f"Counters · t = {sim.controller.latest.frame.t:.2f} s"

        await pilot.press("e")
        await wait_until(pilot, lambda: isinstance(app.screen, ExportResultScreen), timeout=120, what="exported")
        files = {f.kind: f for f in app.screen.files}
        exported = json.loads(files["metrics"].path.read_text(encoding="utf-8"))
        flat = {**exported["robot"], **exported["crowd"]}

        listed = [key for key in LIVE_METRICS if key in flat]
        assert {"goal_reach_rate", "agent_overlaps", "queue_served"} <= set(listed)
        assert [key for key in LIVE_METRICS if key in sim.metrics] == listed, "the panel lists other metrics"
        for key in listed:
            assert metric_text(sim.metrics[key]) == metric_text(flat[key]), key
            assert key in shown and metric_text(flat[key]) in shown, (key, shown)
        assert flat["queue_served"] > 0, "the run is too short to test the queue counters"


@pytest.mark.slow
def test_the_controller_reads_only_the_frames_recorded_since_its_last_measure(tmp_path):
    """The counters' cost follows the frames since the last look, not the run's length."""
    import threading
    import time

    from helpers.handmade import build_hospital_bundle

    from grove_tui.analysis.live_metrics import LiveMetrics
    from grove_tui.scenario.bundle import load_scenario
    from grove_tui.simulation.simulation import Simulation
    from grove_tui.tui.screens.sim_controller import SimulationController
    from grove_tui.world import load_world

    bundle = build_hospital_bundle(tmp_path / "bundle")
    scenario = load_scenario(bundle)
    world = load_world(scenario.world)
    sim = Simulation.from_scenario(scenario, bundle, world=world)
    reads: list[tuple[int, int]] = []
    rows_from = sim.recorder.rows_from

    def spied(start: int):
        reads.append((start, sim.recorder.recorded_rows))
        return rows_from(start)

    sim.recorder.rows_from = spied
    controller = SimulationController(sim, fps=20, speed=8.0, metrics=LiveMetrics(scenario, world))
    stop = threading.Event()
    thread = threading.Thread(target=controller.run, args=(stop.is_set,))
    thread.start()
    try:
        controller.send("play", True)
        deadline = time.monotonic() + 60
        while controller.latest is None or controller.latest.frame.t < 8.0:
            assert time.monotonic() < deadline
            time.sleep(0.05)
        controller.send("play", False)
        time.sleep(0.3)
    finally:
        stop.set()
        thread.join()
    latest = controller.latest
    assert latest.counters is not None and latest.counters.step == latest.frame.step, "paused: the paused instant"
    assert latest.counters.t == pytest.approx(latest.frame.t)
    assert len(reads) >= 4
    # Each look starts where the previous one stopped: no frame is read twice.
    assert all(later[0] == earlier[1] for earlier, later in zip(reads, reads[1:]))


class _SlowSimulation:
    """A simulation a machine cannot run at 8x: each 0.05 s step takes 10 ms of wall time (8x asks 160
    steps a second, 100 fit)."""

    dt = 0.05

    def __init__(self) -> None:
        self.step_count = 0

    @property
    def time(self) -> float:
        return self.step_count * self.dt

    def step(self) -> None:
        import time

        time.sleep(0.01)
        self.step_count += 1

    def frame(self):
        from types import SimpleNamespace

        return SimpleNamespace(t=self.time, step=self.step_count)


@pytest.mark.slow
def test_a_run_behind_its_speed_keeps_publishing_frames():
    """Issue 31: at 8x on a machine that cannot keep up, the picture keeps moving (the backlog used to
    grow to 400 steps done in one go, holding the picture for seconds) and the run still goes faster
    than 1x."""
    import threading
    import time

    from grove_tui.tui.screens.sim_controller import SimulationController

    sim = _SlowSimulation()
    controller = SimulationController(sim, fps=20, speed=8.0)
    stop = threading.Event()
    thread = threading.Thread(target=controller.run, args=(stop.is_set,))
    thread.start()
    published: list[float] = []
    try:
        controller.send("play", True)
        serial = -1
        started = time.monotonic()
        while time.monotonic() - started < 4.0:
            latest = controller.latest
            if latest is not None and latest.serial != serial:
                serial = latest.serial
                published.append(time.monotonic())
            time.sleep(0.005)
    finally:
        stop.set()
        thread.join()
    gaps = [later - earlier for earlier, later in zip(published, published[1:])]
    assert len(published) > 10 and max(gaps) < 1.0, f"longest wait for a new frame {max(gaps):.2f} s"
    assert sim.time > 4.0 * 1.5, f"{sim.time:.1f} simulated seconds in 4 wall seconds"
