"""A group asked to do something and to react to the robot does both, and the report claims both: "six
patients queue at the pharmacy and look at the robot as it passes" queue at the pharmacy counter with the look
around the queue (HuNavSim's pattern: the robot cue first in a fallback around the routine), and the report
claims the queue and the look, each checked on the run. Before, the reading had only the look: reconcile
removed the model's GoTo and Queue, the tree only looked, and the report had no queue claim (the same for a
wait: "four visitors wait in the cafeteria for ten seconds and avoid the robot" kept away from the robot
wherever they stood). Planned from hand-written drafts (no model), and real simulations.

A look around a routine also turns the person to the robot now: the reaction halts the routine after it in the
fallback, and the halt stood the person still after SurprisedNav had turned them to the robot (0/6 looked)."""

from __future__ import annotations

import pytest
from helpers.planned_run import plan_by_hand

from grove_tui.bt.format.xml import read_tree
from grove_tui.generation.draft import DraftGroup, DraftNode
from grove_tui.world import load_world

QUEUE = "Six patients queue at the pharmacy and look at the robot as it passes."
WAIT = ("Four visitors wait in the cafeteria for ten seconds and avoid the robot while the robot drives from the "
        "main entrance to the cafeteria.")
LIBRARY = "eval/understanding/worlds/library.yaml"
READERS = ("Three readers wait at the issue desk for a minute and watch the robot go by while the robot drives "
           "from the entrance foyer to the reading room.")


def _claims(report, kind):
    return [c for g in report.groups for c in g.claims if c.kind == kind]


def _root(run):
    return read_tree((run.bundle / run.op.agents[0].tree).read_text(encoding="utf-8"), "t").main


@pytest.fixture(scope="module")
def patients(tmp_path_factory):
    tree = DraftNode("Sequence", {}, (DraftNode("GoTo", {"target": "pharmacy"}),
                                      DraftNode("Queue", {"service_point": "pharmacy"})))
    return plan_by_hand(load_world("hospital"), "normal", QUEUE, (DraftGroup("patients", 6, "main_corridor", tree),),
                        tmp_path_factory.mktemp("patients") / "b")


@pytest.fixture(scope="module")
def visitors(tmp_path_factory):
    tree = DraftNode("Sequence", {}, (DraftNode("GoTo", {"target": "cafeteria"}),
                                      DraftNode("Wait", {"duration": 10.0})))
    return plan_by_hand(load_world("hospital"), "normal", WAIT, (DraftGroup("visitors", 4, "main_corridor", tree),),
                        tmp_path_factory.mktemp("visitors") / "b")


def test_the_queue_is_kept_inside_the_reaction(patients):
    # "... as it passes": they walk to the counter first and react around the queue there, so the look is not
    # spent on the way (generation/passing_look.react_once_there)
    walk, fallback = _root(patients).children
    assert walk.id == "GoTo" and fallback.id == "ReactiveFallback", [e.id for e in _root(patients).walk()]
    root = fallback
    cue, routine = root.children[0], root.children[-1]
    assert cue.children[0].id in ("IsRobotClose", "IsRobotVisible")
    assert {"SurprisedNav", "LookAtRobot"} & {e.id for e in cue.walk()}
    queue = next(e for e in routine.walk() if e.id == "Queue")
    assert queue.get("service_point") == "pharmacy_counter"


def test_the_report_claims_the_queue_and_the_look(patients):
    queue, = _claims(patients.report, "queue")
    assert queue.place == "pharmacy_counter" and queue.status == "planned", queue
    look, = _claims(patients.report, "robot_look")
    assert look.status == "planned", look


def test_they_queue_and_look_on_the_run(patients):
    report = patients.run(90.0)
    queue, = _claims(report, "queue")
    look, = _claims(report, "robot_look")
    assert queue.status == "holds", queue.evidence
    assert look.status == "holds", look.evidence


def test_the_wait_is_kept_and_claimed(visitors):
    root = _root(visitors)
    assert root.id == "ReactiveFallback"
    routine = root.children[-1]
    assert [e.id for e in routine.walk() if e.id in ("GoTo", "Wait", "StopAndWaitTimerAction")][:1] == ["GoTo"]
    stay, = _claims(visitors.report, "stay")
    assert stay.zone == "cafeteria" and stay.seconds == 10.0, stay
    assert _claims(visitors.report, "robot_avoid")


def test_they_wait_there_and_keep_away_on_the_run(visitors):
    report = visitors.run(90.0)
    stay, = _claims(report, "stay")
    avoid, = _claims(report, "robot_avoid")
    assert stay.status == "holds", stay.evidence
    assert avoid.status == "holds", avoid.evidence


def test_a_wait_with_a_look_in_another_world(tmp_path):
    """Planned only: the wait at the issue desk for its minute, the look around it, both claimed."""
    tree = DraftNode("LookAtRobot", {})  # the model wrote only the reaction
    run = plan_by_hand(load_world(LIBRARY), "normal", READERS, (DraftGroup("readers", 3, "main_corridor", tree),),
                       tmp_path / "b")
    stay, = _claims(run.report, "stay")
    assert stay.place == "issue_desk" and stay.seconds == 60.0, stay
    assert _claims(run.report, "robot_look")
    root = _root(run)
    assert root.id == "ReactiveFallback" and any(e.id == "GoTo" for e in root.children[-1].walk())


def test_a_reaction_alone_is_as_before(tmp_path):
    run = plan_by_hand(load_world("hospital"), "normal", "Two porters stare at the robot in the main corridor.",
                       (DraftGroup("porters", 2, "main_corridor", DraftNode("LookAtRobot", {})),), tmp_path / "b")
    assert not _claims(run.report, "queue")
    # staring at the robot where they are: they stay there, claimed (generation/stay_claims.py)
    stay, = _claims(run.report, "stay")
    assert stay.zone == "main_corridor" and stay.seconds is None
    assert _claims(run.report, "robot_look")
    assert "LookAtRobot" in {e.id for e in _root(run).walk()}
