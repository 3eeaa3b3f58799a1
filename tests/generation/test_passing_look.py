"""A look tied to the moment the robot passes is checked in that moment. "A guide looks up as the robot
passes the desk" was checked as a glance at any time the robot was within 10 m (✓ on a run where the robot
was near the guide for 2 s); now the claim carries the moment (the desk's point), the check counts only the
looks while the robot passes it, and the figure says when it passed and when they looked. Planned from a
hand-written draft (no model) and a real simulation."""

from __future__ import annotations

from dataclasses import replace

import pytest
from helpers.planned_run import plan_by_hand

from grove_tui.generation.draft import DraftGroup, DraftNode
from grove_tui.language.passing_moment import passing_moment
from grove_tui.language.reading import read_prompt
from grove_tui.world import load_world

MUSEUM = "worlds/museum.yaml"
GUIDE = (DraftGroup("guide", 1, "entrance_hall", DraftNode("Wait", {"duration": 120.0})),)


def _look(report):
    return next(c for g in report.groups for c in g.claims if c.kind == "robot_look")


def _with_look(report, claim):
    return replace(report, groups=tuple(replace(g, claims=tuple(claim if c.kind == "robot_look" else c
                                                                for c in g.claims)) for g in report.groups))


@pytest.mark.parametrize("sentence, tied, place", [
    ("A guide looks up as the robot passes the desk.", True, "information_desk"),
    ("Two cleaners glance at the robot as it goes by.", True, None),
    ("Visitors turn to look at the robot when it drives past them.", True, None),
    ("Two visitors look at the robot in the great hall.", False, None),
    ("The children stare at the robot while their parents queue at the ticket desk.", False, None),
])
def test_the_reading_of_a_look_at_the_passing_robot(sentence, tied, place):
    reading = read_prompt(sentence, load_world(MUSEUM))
    lookers = [g for g in reading.groups if g.robot_interaction == "look"]
    assert lookers, reading
    moment = passing_moment(reading.prompt, lookers[0], reading.robot)
    assert (moment is not None) == tied
    if tied:
        assert moment.place == place


@pytest.fixture(scope="module")
def guide(tmp_path_factory):
    world = load_world(MUSEUM)
    run = plan_by_hand(world, "normal", "A guide looks up as the robot passes the desk", GUIDE,
                       tmp_path_factory.mktemp("guide") / "b")
    return world, run, run.run(60.0)


def test_the_look_is_checked_while_the_robot_passes_the_desk(guide):
    world, run, report = guide
    planned = _look(run.report)
    assert planned.moment == "pass" and planned.place == "information_desk" and planned.point is not None, planned
    assert "as the robot passes information_desk" in planned.asked
    checked = _look(report)
    # the look is cued as the robot passes, not as soon as it is within a look's 10 m
    xml = (run.bundle / run.op.agents[0].tree).read_text(encoding="utf-8")
    assert 'threshold="4' in xml and 'threshold="10' not in xml, xml
    assert checked.status == "holds", checked.evidence
    checked = _look(report)
    assert "the robot passed information_desk from t = " in checked.evidence, checked.evidence
    assert "they looked from t = " in checked.evidence or checked.status == "fails", checked.evidence


def test_a_look_at_another_moment_is_not_a_look_as_it_passes(guide):
    world, run, report = guide
    planned = _look(run.report)
    # the same run, the moment put at a place the robot never comes to: no look as it passes there
    far = replace(planned, place="dinosaur_gallery", point=world.zone("dinosaur_gallery").centroid)
    checked = _look(run.check(_with_look(run.report, far), world))
    assert checked.status == "fails" and "never passed dinosaur_gallery" in checked.evidence, checked.evidence
    # checked at any time (the check before), the look on the same run reads ✓
    anytime = replace(far, moment=None, point=None, place=None)
    assert _look(run.check(_with_look(run.report, anytime), world)).status == "holds"
