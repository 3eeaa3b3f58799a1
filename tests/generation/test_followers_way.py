"""People who follow the robot "from the foyer to the computer lab" name the robot's way: it leads them
from the one to the other, and the report claims they arrive. Before, the robot crossed elsewhere (its
clause was empty), nobody went to the computer lab, and the report was all ✓ without a word of it."""

from __future__ import annotations

from helpers.planned_run import plan_by_hand

from grove_tui.generation.draft import DraftGroup, DraftNode
from grove_tui.scenario.report import HOLDS
from grove_tui.world import load_world

LIBRARY = "eval/understanding/worlds/library.yaml"
SENTENCE = "three students follow the robot from the entrance foyer to the computer lab"


def test_the_robot_leads_its_followers_where_they_follow_it_and_they_arrive(tmp_path):
    library = load_world(LIBRARY)
    run = plan_by_hand(library, "normal", SENTENCE,
                       (DraftGroup("students", 3, "entrance_foyer", DraftNode("Wait", {"duration": 5.0})),),
                       tmp_path / "b")
    robot = run.op.robot
    assert library.zone_at(*robot.start).name == "entrance_foyer"
    assert library.zone_at(*robot.goal).name == "computer_lab"
    claims = {c.kind: c for c in run.report.groups[0].claims}
    assert claims["reach"].place == "computer_lab"
    report = run.run(claims["reach"].needs_seconds or 120.0)
    checked = {c.kind: c for c in report.groups[0].claims}
    assert all(c.status == HOLDS for c in report.robot.claims), [c.evidence for c in report.robot.claims]
    assert checked["robot_follow"].status == HOLDS, checked["robot_follow"].evidence
    assert checked["reach"].status == HOLDS, checked["reach"].evidence
    # the reader gives the robot the followers' way ("from the foyer", "to the computer lab"), so it is
    # claimed to start in the one and reach the other
    places = {c.place for c in run.report.robot.claims if c.kind == "robot_reach"}
    assert "computer_lab" in places
