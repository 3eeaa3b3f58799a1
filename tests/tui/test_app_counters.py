"""Issue 21 item 5: the simulation's counters are metrics.json's numbers, under metrics.json's names."""

from __future__ import annotations

import json

import pytest
from helpers.app import generate_to_simulation
from helpers.app import (
    fake_llm_backend,
    test_settings,
    wait_until,
)
from textual.widgets import Static

from grove_tui.tui.app import GroveApp
from grove_tui.tui.screens.export import ExportResultScreen
from grove_tui.tui.screens.simulation import LIVE_METRICS, metric_text

pytestmark = pytest.mark.anyio


async def test_counters_shown_equal_the_exported_metrics_json_of_the_same_run(tmp_path):
    app = GroveApp(fake_llm_backend(tmp_path / "runs"), test_settings(tmp_path))
    async with app.run_test(size=(120, 40)) as pilot:
        sim = await generate_to_simulation(pilot, app)
        await pilot.press("f", "space")  # as fast as possible: queues form and people get served
        await wait_until(pilot, lambda: sim.controller.latest.frame.t >= 30.0, timeout=120, what="30 s simulated")
        await pilot.press("space")
        await wait_until(pilot, lambda: not sim.controller.latest.playing, what="paused")
        paused_at = sim.controller.latest.frame.step
        await wait_until(pilot, lambda: sim.metrics_step == paused_at, timeout=30, what="counters of the paused run")
        shown = str(sim.query_one("#counters", Static).render())

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
