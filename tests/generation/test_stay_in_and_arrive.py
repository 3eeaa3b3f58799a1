"""Nobody vanishes unless they leave, and reached means arrived.

Before: in the mall, "a guard stands at the main entrance for two minutes, then walks to the food court
while the robot follows her" lost the guard through the door at 11 s (the crowd pushed her over its
line and the simulation removed her as if she had left), so her wait and walk were "not checked"; in
the library, "the robot leads a visitor to the computer lab" placed the visitor in the lab (the zone
their sentence names), and "reach" was ✓ at t = 0.1 s."""

from __future__ import annotations

import numpy as np
import pytest
from helpers.planned_run import plan_by_hand

from grove_tui.analysis.arrival import Arrivals
from grove_tui.analysis.metrics import Trajectories
from grove_tui.generation.draft import DraftGroup, DraftNode
from grove_tui.scenario.events import SimEvent, read_events
from grove_tui.scenario.report import FAILS, HOLDS, Claim, GroundingReport, GroupGrounding
from grove_tui.analysis.left_run import gone_reason
from grove_tui.world import load_world

GUARD = "a guard stands at the main entrance for two minutes, then walks to the food court while the robot follows her"
LED = "the robot leads a visitor to the computer lab"


def test_a_guard_at_the_main_entrance_stays_in_the_run(tmp_path):
    mall = load_world("worlds/mall.yaml")
    tree = DraftNode("Sequence", {}, (DraftNode("GoTo", {"target": "main_entrance"}),
                                      DraftNode("Wait", {"duration": 120.0}),
                                      DraftNode("GoTo", {"target": "food_court"})))
    run = plan_by_hand(mall, "normal", GUARD, (DraftGroup("guard", 1, "south_entrance_hall", tree),),
                       tmp_path / "bundle", as_the_pipeline=True)
    run.run(30.0)
    events = read_events(run.bundle / "events.jsonl")
    assert not [e for e in events if e.kind in ("left_building", "evacuated")]
    traj = Trajectories.from_csv(run.bundle / "trajectories.csv")
    assert np.isfinite(traj.people[:, :, 0]).all()  # in every frame of the run
    building = mall.outline()
    import shapely
    assert shapely.contains_xy(building, traj.people[:, :, 0].ravel(), traj.people[:, :, 1].ravel()).all()


def test_a_person_pushed_out_who_was_not_asked_to_leave_is_a_cross_not_unchecked():
    gone = [SimEvent(11.0, 1, "left_building", "main_entrance")]
    reason = gone_reason("stay", [1], {1: gone})
    assert "pushed out" in reason and "11.0" in reason
    assert gone_reason("evacuate", [1], {1: gone}) == ""  # leaving is what they were asked
    assert gone_reason("stay", [2], {1: gone}) == ""


@pytest.fixture(scope="module")
def led(tmp_path_factory):
    library = load_world("eval/understanding/worlds/library.yaml")
    # the model put the visitor in the lab, as the sentence names it
    run = plan_by_hand(library, "normal", LED, (DraftGroup("visitor", 1, "computer_lab",
                                                           DraftNode("Wait", {"duration": 10.0})),),
                       tmp_path_factory.mktemp("led") / "bundle", as_the_pipeline=True)
    return library, run


def test_the_led_visitor_starts_where_the_robot_picks_them_up(led):
    library, run = led
    (visitor,) = run.op.agents
    assert library.zone_at(*visitor.start).name != "computer_lab"
    robot = run.op.robot
    assert np.hypot(visitor.start[0] - robot.start[0], visitor.start[1] - robot.start[1]) < 12.0


def test_someone_who_starts_at_their_destination_has_not_reached_it(led):
    library, run = led
    (visitor,) = run.op.agents
    start_zone = library.zone_at(*visitor.start).name
    run.run(5.0)
    planned = GroundingReport(LED, (GroupGrounding("a visitor", "visitor", (
        Claim("reach", start_zone, "walk there", zone=start_zone, place=start_zone, needs_seconds=60.0),),
        (visitor.id,)),))
    checked = run.check(planned, library)
    claim = checked.groups[0].claims[0]
    assert claim.status != HOLDS and "started there" in claim.evidence


def test_arrivals_count_only_a_coming_back():
    arrivals = Arrivals(2)
    inside = np.array([[True, False], [False, False], [True, True]])
    present = np.ones_like(inside)
    arrived = arrivals.arrived(inside, present)
    assert arrived.tolist() == [[False, False], [False, False], [True, True]]
    assert arrivals.started_there() == 1
    assert FAILS != HOLDS


def test_guards_waiting_by_an_exit_stand_beside_its_opening(tmp_path):
    """'Two security guards wait by the main entrance' stood 0.6 m inside the door's centre, in the way
    of everyone leaving and pushed out by them: they stand beside the opening, and are checked there."""
    mall = load_world("worlds/mall.yaml")
    door = mall.find("main_entrance")
    tree = DraftNode("Sequence", {}, (DraftNode("GoTo", {"target": "main_entrance"}),
                                      DraftNode("Wait", {"duration": 600.0})))
    sentence = "two security guards wait by the main entrance"
    run = plan_by_hand(mall, "normal", sentence, (DraftGroup("guard", 2, "south_entrance_hall", tree),),
                       tmp_path / "bundle")
    checked = run.run(40.0)
    traj = Trajectories.from_csv(run.bundle / "trajectories.csv")
    for x, y in traj.people[-1]:
        along = abs((x - door.position[0]) * door.along[0] + (y - door.position[1]) * door.along[1])
        assert along > door.width / 2.0, (x, y)
    stay = next(c for c in checked.groups[0].claims if c.kind == "stay")
    assert stay.status == HOLDS, stay.evidence
