"""A robot that goes somewhere "via the fountain" passes by the fountain itself, where the report checks
it (near the thing's point), not anywhere in the atrium it stands in. Before, the path only had to cross
the fountain's zone, which its straight way already did: the robot never came by the fountain and the
report's robot_via was ✗ on every run of the sentence."""

from __future__ import annotations

import numpy as np
from helpers.planned_run import plan_by_hand

from grove_tui.generation.draft import DraftGroup, DraftNode
from grove_tui.scenario.report import HOLDS
from grove_tui.world import load_world

SENTENCE = ("Ten shoppers stroll around the food court, six people sit at the atrium benches and twenty walk from "
            "the west mall to the east mall, while the robot goes to the information desk via the fountain.")


def test_the_robot_passes_by_the_thing_it_goes_via_and_the_report_says_so(tmp_path):
    mall = load_world("mall")
    groups = (DraftGroup("shoppers", 10, "food_court", DraftNode("Wander", {"zone": "food_court", "duration": 120.0})),
              DraftGroup("people", 6, "main_atrium", DraftNode("Wait", {"duration": 5.0})),
              DraftGroup("people", 20, "west_mall", DraftNode("GoTo", {"target": "east_mall"})))
    run = plan_by_hand(mall, "normal", SENTENCE, groups, tmp_path / "b")
    fountain = mall.find("fountain").interaction_point
    path = np.asarray(run.op.robot.path)
    # the way, sampled every 10 cm, comes by the fountain's point
    seg = [a + (b - a) * s for a, b in zip(path[:-1], path[1:]) for s in np.linspace(0, 1, 50)]
    assert min(float(np.hypot(*(p - np.asarray(fountain)))) for p in seg) <= 0.75
    via = [c for c in run.report.robot.claims if c.kind == "robot_via"]
    assert via and via[0].place == "fountain"
    report = run.run(max(c.needs_seconds or 0.0 for c in run.report.robot.claims))
    checked = {c.kind: c for c in report.robot.claims}
    assert checked["robot_via"].status == HOLDS, checked["robot_via"].evidence
    assert checked["robot_reach"].status == HOLDS, checked["robot_reach"].evidence
