"""Round 46 (r46a): a smoke one goes out for or has is a cigarette, not a hazard ("out to the terrace for a
smoke", "nips out for a quick smoke", "having a crafty smoke"): the walk stays a walk, no evacuation
(language/a_smoke.py). Smoke as a hazard still evacuates."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt", [
    ("hotel", "A guest nips out for a quick smoke."),
    ("brewery", "Two brewers wander from the tap room out to the yard for a smoke."),
    ("bus_station", "A driver heads outside to have a crafty smoke."),
    ("hospital", "A porter slips out for a smoke."),
])
def test_a_smoke_gone_out_for_is_no_hazard(read, world, prompt):
    assert all(g.intent != "evacuate" for g in read(world, prompt).groups)


@pytest.mark.parametrize("world,prompt", [
    ("hotel", "A thick smoke fills the lobby and the guests leave."),
    ("hospital", "Smoke pours out of the pharmacy and the nurses leave."),
])
def test_smoke_as_a_hazard_still_evacuates(read, world, prompt):
    assert read(world, prompt).groups[-1].intent == "evacuate"
