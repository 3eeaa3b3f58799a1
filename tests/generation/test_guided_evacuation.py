"""People the robot guides out of a building walk behind it to their exit, then out
(generation/guided.py, reconcile.py, planning.py): "the staff evacuate while the robot guides them to
the exit" has the staff start behind the robot, among whom it sets off, follow it at an evacuation's
pace and leave when it is at the door; the people the sentence sends out on their own still go.
Planned from hand-written drafts (no model) and run in the real simulation: the report's ✓ are measured."""

from __future__ import annotations

import pytest
from helpers.planned_run import plan_by_hand

from grove_tui.generation.draft import DraftGroup, DraftNode
from grove_tui.generation.guided import GUIDING_VEL
from grove_tui.scenario.report import HOLDS
from grove_tui.world import load_world

# (world, sentence, the draft's group labels, the guided group's label, the others')
CASES = {
    "office-guides-them": ("office", "Fire in the kitchen: the staff evacuate while the robot guides them to the exit "
                           "and six employees in the open plan office evacuate on their own", ("staff", "employees")),
    "museum-leads-out": ("museum", "A fire breaks out: visitors in the egyptian gallery evacuate while the robot leads "
                         "them out through the main entrance and three guards leave through the nearest exit",
                         ("visitors", "guards")),
    "hospital-escorts": ("hospital", "Fire alarm: the patients in the main waiting room evacuate while the robot "
                         "escorts them to the fire exit and three nurses evacuate on their own", ("patients", "nurses")),
}


@pytest.fixture(scope="module", params=sorted(CASES))
def guided_run(request, tmp_path_factory):
    world_name, sentence, labels = CASES[request.param]
    world = load_world(world_name)
    # what the model writes for an evacuation: follow the field out
    leave = DraftNode("Sequence", {}, (DraftNode("FollowVelocityField", {"exit": world.exits()[0].name}),))
    run = plan_by_hand(world, "emergency", sentence, tuple(DraftGroup(label, 4, world.zones[0].name, leave)
                                                           for label in labels),
                       tmp_path_factory.mktemp(request.param) / "bundle")
    seconds = max(c.needs_seconds or 0.0 for g in run.report.groups for c in g.claims) + 10.0
    return run, run.run(seconds)


def _claim(group, kind):
    return next(c for c in group.claims if c.kind == kind)


def test_the_guided_go_with_the_robot_and_out(guided_run):
    run, checked = guided_run
    guided = checked.groups[0]
    follow = _claim(guided, "robot_follow")
    assert follow.status == HOLDS, follow.evidence
    out = _claim(guided, "evacuate")
    assert out.status == HOLDS, out.evidence
    assert run.op.robot is not None and run.op.robot.max_vel == GUIDING_VEL  # an evacuation's pace, not 0.8 m/s
    assert checked.robot is not None and all(c.status == HOLDS for c in checked.robot.claims)


def test_the_people_not_guided_still_evacuate_on_their_own(guided_run):
    run, checked = guided_run
    for group in checked.groups[1:]:
        assert not any(c.kind == "robot_follow" for c in group.claims)
        out = _claim(group, "evacuate")
        assert out.status == HOLDS, out.evidence
    trees = [g for g in run.op.trees.values() if "ApproachRobot" in {n.id for n in g.nodes()}]
    guided_members = set(run.report.groups[0].members)
    assert len(trees) == len(guided_members)  # only the guided follow the robot


def test_the_guided_and_their_guide_end_at_one_exit(guided_run):
    """The robot and the people it guides end at one place, in the trees, the plan and the claims: the
    group's evacuation claim asks for the robot's exit alone (not "any exit"), and the run shows them out
    through it."""
    run, checked = guided_run
    assert checked.robot is not None
    reach = next(c for c in checked.robot.claims if c.kind == "robot_reach" and c.place)
    out = _claim(checked.groups[0], "evacuate")
    assert out.exits == (reach.place,), (out.asked, reach.place)
    assert reach.place in out.asked
    members = set(run.report.groups[0].members)
    exits = {n.get("exit") for agent, doc in run.op.trees.items() for n in doc.nodes()
             if n.id == "FollowVelocityField" and _agent_id(agent) in members}
    assert exits <= {reach.place}, exits
    assert out.status == HOLDS and f"through {reach.place}" in out.evidence, out.evidence


def _agent_id(key) -> int:
    return int(str(key).rsplit("_", 1)[-1].split(".")[0])
