"""The robot's carrying task: "the robot carries books from the issue desk to the reading room" goes to the
pick-up place first, stops there a moment, then drives to the drop-off; "fetches X from A" brings it back
where it set off. Before, the robot set off from the desk itself and drove on, and the report checked only
that it reached the reading room. Hand-written drafts (no model) and real simulations."""

from __future__ import annotations

import math

import pytest
from helpers.planned_run import plan_by_hand

from grove_tui.generation.draft import DraftGroup, DraftNode
from grove_tui.language.model import RobotReading
from grove_tui.language.robot_errands import robot_errand
from grove_tui.world import load_world

LIBRARY = "eval/understanding/worlds/library.yaml"


def _readers(n: int = 2) -> tuple[DraftGroup, ...]:
    return (DraftGroup("student", n, "reading_room", DraftNode("Wait", {"duration": 200})),)


@pytest.mark.parametrize("text, kind, pickup, dropoff", [
    ("The robot carries books from the issue desk to the reading room", "carry", "issue_desk", "reading_room"),
    ("The robot fetches a map from the cloakroom", "fetch", "cloakroom", None),
    ("The robot delivers a parcel to the cafe", "deliver", None, "cafe"),
])
def test_the_errand_names_pick_up_and_drop_off(text, kind, pickup, dropoff):
    start = pickup if kind == "carry" else None
    via = (pickup,) if kind == "fetch" else ()
    robot = RobotReading("cross", start=start, destination=dropoff, via=via, text=text)
    errand = robot_errand(robot)
    assert errand is not None and (errand.kind, errand.pickup, errand.dropoff) == (kind, pickup, dropoff)


@pytest.mark.parametrize("text", ["The robot crosses from the foyer to the cafe",
                                  "The robot moves from the foyer to the cafe",
                                  "The robot takes the long way from the foyer to the cafe"])
def test_a_crossing_is_no_errand(text):
    assert robot_errand(RobotReading("cross", start="entrance_foyer", destination="cafe", text=text)) is None


@pytest.fixture(scope="module")
def carried(tmp_path_factory):
    world = load_world(LIBRARY)
    sentence = "Two students wait in the reading room while the robot carries books from the issue desk to the " \
               "reading room"
    run = plan_by_hand(world, "normal", sentence, _readers(), tmp_path_factory.mktemp("carry") / "b")
    return world, run


def test_the_robot_goes_to_the_pick_up_first_and_stops(carried):
    world, run = carried
    robot = run.op.robot
    desk = world.find("issue_desk")
    zone = world.zone_of_place("issue_desk")
    start_zone = world.zone_at(*robot.start)
    assert start_zone is not None and start_zone.name not in (zone, "reading_room"), robot.start
    assert len(robot.stops) == 1
    x, y, seconds = robot.stops[0]
    assert seconds > 0 and math.dist((x, y), desk.interaction_point) < 3.0, (robot.stops, desk.interaction_point)
    kinds = [c.kind for c in run.report.robot.claims]
    assert kinds == ["robot_pickup", "robot_dropoff"], run.report.robot.claims


def test_both_legs_are_checked_on_the_run(carried):
    _, run = carried
    report = run.run(150.0)
    claims = {c.kind: c for c in report.robot.claims}
    assert claims["robot_pickup"].status == "holds", claims["robot_pickup"].evidence
    assert claims["robot_dropoff"].status == "holds", claims["robot_dropoff"].evidence
    assert "after leaving" in claims["robot_dropoff"].evidence


def test_a_fetch_comes_back_where_it_set_off(tmp_path):
    world = load_world(LIBRARY)
    sentence = "Two students wait in the reading room while the robot fetches a book from the stacks"
    run = plan_by_hand(world, "normal", sentence, _readers(), tmp_path / "b")
    robot = run.op.robot
    assert robot.stops and math.dist(robot.start, robot.goal) < 0.5, robot
    assert world.zone_at(*robot.start).name != "stacks"
    report = run.run(150.0)
    claims = {c.kind: c for c in report.robot.claims}
    assert claims["robot_pickup"].status == "holds", claims["robot_pickup"].evidence
    assert claims["robot_dropoff"].status == "holds", claims["robot_dropoff"].evidence


def test_a_delivery_passes_the_people_who_react_to_the_robot(tmp_path):
    # "the robot never came within 6 m of them": the errand's route ignored the rooms of people who react
    world = load_world("worlds/hospital.yaml")
    sentence = "Six patients queue at the pharmacy and keep away from the robot while the robot delivers medicine " \
               "to the ward"
    run = plan_by_hand(world, "normal", sentence,
                       (DraftGroup("patient", 6, "pharmacy", DraftNode("Queue", {"service_point": "pharmacy_counter"})),),
                       tmp_path / "b")
    report = run.run(120.0)
    claims = {c.kind: c for g in report.groups for c in g.claims}
    # the route now comes by their room (whether a queue grazed at the edge of 6 m steps 0.5 m away is the
    # avoid check's own matter)
    assert "never came within" not in claims["robot_avoid"].evidence, claims["robot_avoid"].evidence
    robot = {c.kind: c for c in report.robot.claims}
    assert robot["robot_dropoff"].status == "holds", robot
