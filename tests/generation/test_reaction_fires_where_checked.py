"""A reaction around a routine fires from as far as the report checks it: "walk to the reading room and avoid
the robot" is checked on everyone the robot comes within 6 m of, "glance at the robot" on the time it is within
10 m; HuNavSim's nearer triggers (5 m scared, 8 m surprised), seeing only ahead, left people the check counted
without a reaction (a false ✗; the robot passes people queuing with their backs to it). Planned from hand-written
drafts (no model), and one run in the real simulation."""

from __future__ import annotations

import re

import pytest
from helpers.planned_run import plan_by_hand

from grove_tui.generation.draft import DraftGroup, DraftNode
from grove_tui.world import load_world

CASES = [
    ("eval/understanding/worlds/library.yaml", "Four students walk to the reading room and avoid the robot.",
     "reading_room", 4, "robot_avoid"),
    ("hospital", "Three visitors walk to the cafeteria, keeping well away from the robot.", "cafeteria", 3,
     "robot_avoid"),
    ("museum", "Five visitors walk to the gift shop, staring at the robot as it passes.", "gift_shop", 5, "robot_look"),
]


@pytest.mark.parametrize("world_name, sentence, place, people, kind", CASES)
def test_the_trigger_reaches_as_far_as_the_check(world_name, sentence, place, people, kind, tmp_path):
    world = load_world(world_name)
    tree = DraftNode("Sequence", {}, (DraftNode("GoTo", {"target": place}),))
    run = plan_by_hand(world, "normal", sentence, (DraftGroup("people", people, place, tree),), tmp_path / "b")
    claim = next(c for g in run.report.groups for c in g.claims if c.kind == kind)
    xml = (run.bundle / run.op.agents[0].tree).read_text(encoding="utf-8")
    # whatever their heading: a robot behind them is within the check's reach too
    assert "<IsRobotVisible" not in xml
    triggers = [float(d) for d in re.findall(r'<IsRobotClose[^>]*threshold="([0-9.]+)"', xml)]
    assert triggers, xml
    assert min(triggers) >= (claim.distance or 0.0), (triggers, claim.distance)
