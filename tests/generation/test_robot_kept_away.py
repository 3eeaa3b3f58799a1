"""A reaction claim says why it could not fire, and a robot the sentence gives no task passes the people
asked to react to it (analysis/robot_kept_away.py, generation/passing_reactors.py). Planned from
hand-written drafts (no model) and run in the real simulation."""

from __future__ import annotations

import numpy as np
import pytest
from helpers.planned_run import plan_by_hand

from grove_tui.generation.draft import DraftGroup, DraftNode
from grove_tui.analysis.robot_kept_away import REACH
from grove_tui.generation.passing_reactors import widest_gap
from grove_tui.language.reading import read_prompt
from grove_tui.scenario.report import HOLDS
from grove_tui.world import load_world


def _plan(world_path: str, sentence: str, out):
    world = load_world(world_path)
    reading = read_prompt(sentence, world)
    groups = tuple(DraftGroup(g.label, g.count.value or 3, g.start or g.location or world.zones[0].name,
                              DraftNode("Wait", {"duration": 5.0})) for g in reading.groups)
    return plan_by_hand(world, "normal", sentence, groups, out, as_the_pipeline=True)


def test_a_robot_waiting_elsewhere_is_the_reason_the_look_cannot_fire(tmp_path):
    run = _plan("worlds/office.yaml", "The robot waits in the boardroom while two employees in the kitchen look at it",
                tmp_path / "b")
    checked = run.run(30.0)
    look = next(c for g in checked.groups for c in g.claims if c.kind == "robot_look")
    assert look.status != HOLDS
    assert "the robot's task" in look.evidence and "waits" in look.evidence, look.evidence
    assert "came within" in look.evidence and " m of them" in look.evidence, look.evidence


# people who react to the robot around a routine of their own, the robot given no task
NO_TASK = {
    "airport-queue-glance": ("worlds/airport.yaml",
                             "Six passengers queue at check-in counter A and two of them glance at the robot"),
    "library-queue-glance": ("eval/understanding/worlds/library.yaml",
                             "Four students queue at the issue desk and two of them glance at the robot"),
    "station-queue-glance": ("worlds/station.yaml",
                             "Six commuters queue at the ticket office and three of them glance at the robot"),
    "hospital-wait-look": ("worlds/hospital.yaml", "Five patients wait in the main waiting room and look at the robot"),
}


@pytest.mark.parametrize("case", sorted(NO_TASK))
def test_a_robot_with_no_task_passes_the_people_who_react_to_it(tmp_path, case):
    world_path, sentence = NO_TASK[case]
    run = _plan(world_path, sentence, tmp_path / "b")
    assert run.op.robot is not None and run.op.robot.task == "cross"
    reacting = {m for g in run.report.groups if any(c.kind == "robot_look" for c in g.claims) for m in g.members}
    points = [tuple(a.goals[-1]) if a.goals else tuple(a.start) for a in run.op.agents if a.id in reacting]
    assert points
    # within a look's reach of everyone (a room of people spread 13 m wide is not within PASS_NEAR of one way)
    assert widest_gap(np.asarray(run.op.robot.path), points) <= REACH["robot_look"] - 1.0


def test_the_queue_glance_holds_on_the_run(tmp_path):
    """On main the robot's way ran 11.6 m from the back of the queue: ✗ with no cause."""
    run = plan_by_hand(load_world("worlds/airport.yaml"), "queuing", NO_TASK["airport-queue-glance"][1],
                       (DraftGroup("passengers", 6, "check_in_hall",
                                   DraftNode("Queue", {"service_point": "check_in_counter_a"})),),
                       tmp_path / "b", as_the_pipeline=True)
    looks = [c for g in run.run(90.0).groups for c in g.claims if c.kind == "robot_look"]
    assert looks and all(c.status == HOLDS for c in looks), [c.evidence for c in looks]


def test_the_cause_names_the_members_the_robot_never_came_near():
    """"The robot follows a visitor ... while two employees glance at it": one employee had the robot within
    8.2 m, the other never nearer than 11.7 m; the ✗ "1/2 looked" now says the follow kept it from that one."""
    from grove_tui.analysis.robot_kept_away import kept_away
    from grove_tui.scenario.report import Claim, RobotGrounding
    robot = RobotGrounding("follow", "The robot follows a visitor from reception to the kitchen", ())
    look = Claim("robot_look", "look at the robot at least once", "SurprisedNav")
    text = kept_away(look, np.array([8.2, 11.7]), robot)
    assert "follows a visitor" in text and "1 of them" in text and "11.7 m" in text
    assert kept_away(look, np.array([8.2, 9.0]), robot) == ""


def test_the_note_says_the_robots_wait_keeps_it_from_them_not_the_floor(tmp_path):
    """Drivers 18 m from a robot told to wait at bay 3 were noted "no free floor beside the robot's route"."""
    run = _plan("eval/understanding/worlds/bus_station.yaml",
                "Six passengers queue at the ticket desk while the robot waits at bay 3 and two drivers in the rest "
                "room look at it", tmp_path / "b")
    notes = [n for n in run.report.repairs if "group 'driver'" in n]
    assert any("the robot waits as the sentence asks" in n and " m from " in n for n in notes), notes
    assert not any("no free floor" in n for n in notes), notes
