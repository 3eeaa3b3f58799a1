"""Issue 28: the app checks the grounding report while the run plays and shows it once every claim is decided."""

from __future__ import annotations

import pytest
from helpers.app import fake_llm_session, generate_to_simulation, test_settings, wait_until

from grove_tui.tui.app import GroveApp
from grove_tui.tui.widgets.grounding import GroundingPanel

pytestmark = pytest.mark.anyio


@pytest.mark.slow
async def test_the_checked_report_updates_during_the_run_and_opens_when_decided(tmp_path):
    app = GroveApp(fake_llm_session(tmp_path / "runs"), test_settings(tmp_path))
    async with app.run_test(size=(80, 24)) as pilot:
        sim = await generate_to_simulation(pilot, app)
        panel = sim.query_one("#sim-grounding", GroundingPanel)
        assert not panel.display  # the agent's live tree shows until the report is asked for or decided
        await pilot.press("space")  # play at 1x: the first checks come while the queue is still forming
        await wait_until(pilot, lambda: sim.grounding is not None, timeout=60, what="a first live check")
        first = sim.grounding
        assert first.run is not None and first.run.partial
        await pilot.press("f")  # then as fast as possible until the people have queued and been served
        await wait_until(pilot, lambda: panel.display, timeout=180, what="the checked report shown by itself")
        report = sim.grounding
        assert report.run.seconds > first.run.seconds, "the report was not updated during the run"
        queue = [c for g in report.groups for c in g.claims if c.kind == "queue"]
        assert queue and queue[0].status == "holds" and "served" in queue[0].evidence
        assert "✓" in panel.title()
