"""People asked to be somewhere and keep away from the robot give way inside their place and go back to their
routine once the robot has gone: "five visitors wander in the gift shop and keep away from the robot while the
robot crosses from the entrance hall to the cafe". AvoidRobot ran 6 m straight away from the robot, which out
of an 8 m shop is out of the shop; the robot parked in the café 5 m from it and kept them out for good (one
never came back, the wander claim a true ✗ of a run that did not do what was asked). Hand-written drafts, real
simulations."""

from __future__ import annotations

import csv

import pytest
import shapely
from helpers.planned_run import plan_by_hand

from grove_tui.generation.draft import DraftGroup, DraftNode
from grove_tui.world import load_world

SHOP = "Five visitors wander in the gift shop and keep away from the robot while the robot crosses from the " \
       "entrance hall to the cafe"


def _outside(bundle, zone, ids):
    """Per person, the seconds spent out of `zone` (with a doorway's margin) and whether they end in it."""
    polygon = zone.buffer(0.4)
    seen: dict[int, list[bool]] = {}
    for row in csv.DictReader((bundle / "trajectories.csv").open()):
        i = int(row["id"])
        if i in ids:
            seen.setdefault(i, []).append(bool(polygon.covers(shapely.Point(float(row["x"]), float(row["y"])))))
    return {i: (sum(not v for v in flags), flags[-1]) for i, flags in seen.items()}


@pytest.fixture(scope="module")
def shop(tmp_path_factory):
    world = load_world("worlds/museum.yaml")
    run = plan_by_hand(world, "normal", SHOP, (DraftGroup("visitor", 5, "gift_shop",
                                                          DraftNode("Wander", {"zone": "gift_shop"})),),
                       tmp_path_factory.mktemp("shop") / "b")
    return world, run, run.run(120.0)


def test_visitors_keep_away_inside_the_shop(shop):
    world, run, report = shop
    claims = {c.kind: c for g in report.groups for c in g.claims}
    assert claims["robot_avoid"].status == "holds", claims["robot_avoid"].evidence
    assert claims["wander"].status == "holds", claims["wander"].evidence
    ids = {a.id for a in run.op.agents}
    out = _outside(run.bundle, world.zone("gift_shop").polygon, ids)
    dt = 120.0 / max(len(next(iter(out.values()))) if out else 1, 1)
    for i, (frames, last_in) in out.items():
        assert last_in, f"visitor {i} ended outside the shop"
        assert frames * dt < 10.0, f"visitor {i} spent {frames * dt:.0f} s out of the shop"


def test_the_robot_still_drives_its_way(shop):
    _, _, report = shop
    robot = {c.kind: c for c in report.robot.claims}
    assert robot["robot_reach"].status == "holds", report.robot.claims


def test_people_who_queue_and_keep_away_stay_at_their_queue(tmp_path):
    world = load_world("worlds/museum.yaml")
    sentence = "Six visitors queue at the cloakroom and keep away from the robot while the robot crosses from the " \
               "entrance hall to the cafe"
    run = plan_by_hand(world, "normal", sentence, (DraftGroup("visitor", 6, "entrance_hall",
                                                              DraftNode("Queue", {"service_point": "cloakroom"})),),
                       tmp_path / "b")
    report = run.run(120.0)
    claims = {c.kind: c for g in report.groups for c in g.claims}
    assert claims["robot_avoid"].status in ("holds", "unchecked"), claims["robot_avoid"].evidence
    assert claims["queue"].status == "holds", claims["queue"].evidence


def test_one_who_keeps_away_walks_back_in_when_past_the_outline(tmp_path):
    """"a nervous visitor avoids the robot in the entrance hall": giving way, the visitor stepped 0.4 m past
    the hall's east side and stood there for the rest of the run (half a metre past the outline still
    counted as in the hall for the simulation, not for the stay check: 25 % of the run in it, a ✗ of a run
    that did not do what was asked). Now the simulation judges the place as the check does."""
    world = load_world("worlds/museum.yaml")
    sentence = "a nervous visitor avoids the robot in the entrance hall"
    run = plan_by_hand(world, "normal", sentence, (DraftGroup("visitor", 1, "entrance_hall",
                                                              DraftNode("Wait", {"duration": 600.0})),),
                       tmp_path / "b")
    report = run.run(90.0)
    claims = {c.kind: c for g in report.groups for c in g.claims}
    assert claims["robot_avoid"].status in ("holds", "unchecked"), claims["robot_avoid"].evidence
    assert claims["stay"].status == "holds", claims["stay"].evidence
