"""People the sentence has wander but puts nowhere ("five tourists wander around", "watching the skaters go
round") wander where they start. A model's plain wait there gave a report claiming a wander in their zone that
the run could only fail (0 m walked). Planned from hand-written drafts (no model) and run in the real
simulation."""

from __future__ import annotations

import pytest
from helpers.planned_run import plan_by_hand

from grove_tui.generation.draft import DraftGroup, DraftNode
from grove_tui.scenario.report import HOLDS
from grove_tui.world import load_world

# (world, sentence, the zone the model spawns them in)
CASES = [
    ("museum", "Five tourists wander around while the robot waits at the information desk.", "great_hall"),
    ("mall", "A few teenagers mill about.", "atrium"),
    ("office", "Two interns roam aimlessly as the robot crosses the open plan office.", "open_plan_office"),
]
WAIT = DraftNode("Wait", {"duration": 60.0})


@pytest.mark.parametrize("world_name, sentence, zone", CASES)
def test_a_wait_the_model_writes_becomes_a_wander_where_they_start(world_name, sentence, zone, tmp_path):
    world = load_world(world_name)
    run = plan_by_hand(world, "normal", sentence, (DraftGroup("people", 3, zone, WAIT),), tmp_path / "b")
    (group,) = run.report.groups
    wander = next(c for c in group.claims if c.kind == "wander")
    trees = [(run.bundle / a.tree).read_text(encoding="utf-8") for a in run.op.agents]
    assert all("<Wander" in t and f'zone="{wander.zone}"' in t for t in trees), trees[0]
    assert world.zone_at(*run.op.agents[0].start).name == wander.zone


def test_they_are_measured_to_wander(tmp_path):
    world_name, sentence, zone = CASES[0]
    world = load_world(world_name)
    run = plan_by_hand(world, "normal", sentence, (DraftGroup("people", 3, zone, WAIT),), tmp_path / "b")
    seconds = max(c.needs_seconds or 0.0 for g in run.report.groups for c in g.claims) + 10.0
    checked = run.run(seconds)
    wander = next(c for c in checked.groups[0].claims if c.kind == "wander")
    assert wander.status == HOLDS, wander.evidence
