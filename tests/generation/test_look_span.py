"""A glance is not a stare. "Six patients queue at the pharmacy and glance at the robot" was checked as facing
the robot half the time it was within 10 m, which a glance need not do: a faithful run got ✗ (3/6 at 47%).
Now a glance is one look of GLANCE_SECONDS at least, the run turns them to it once and briefly, and a stare
("stare at the robot") is checked as facing it most of the time it is near, with the reaction coming back
while it is. Planned from hand-written drafts (no model) and real simulations."""

from __future__ import annotations

from dataclasses import replace

import pytest
from helpers.planned_run import plan_by_hand

from grove_tui.analysis.outcomes import GLANCE_SECONDS
from grove_tui.bt.format.xml import read_tree
from grove_tui.generation.draft import DraftGroup, DraftNode
from grove_tui.generation.look_span import GLANCE_REACTION
from grove_tui.language.look_spans import look_span
from grove_tui.language.reading import read_prompt
from grove_tui.world import load_world

HOSPITAL = "worlds/hospital.yaml"
QUEUE = (DraftGroup("patient", 6, "pharmacy", DraftNode("Queue", {"service_point": "pharmacy"})),)
SENTENCE = "Six patients queue at the pharmacy and {verb} at the robot while the robot drives from the entrance " \
           "lobby to the cafeteria."


def _look(report):
    return next(c for g in report.groups for c in g.claims if c.kind == "robot_look")


def _surprised(run):
    xml = (run.bundle / run.op.agents[0].tree).read_text(encoding="utf-8")
    return next(e for e in read_tree(xml, "t").nodes() if e.id == "SurprisedNav")


@pytest.mark.parametrize("sentence, span", [
    ("Two cleaners glance at the robot as it passes.", "glance"),
    ("Two visitors look at the robot in the lobby.", "glance"),
    ("A man notices the robot and keeps walking to the cafeteria.", "glance"),
    ("The children stare at the robot.", "watch"),
    ("Three nurses watch the robot while it drives to the pharmacy.", "watch"),
    ("Two porters keep looking at the robot.", "watch"),
])
def test_the_span_of_a_look(sentence, span):
    reading = read_prompt(sentence, load_world(HOSPITAL))
    lookers = [g for g in reading.groups if g.robot_interaction == "look"]
    assert lookers and look_span(lookers[0]) == span


@pytest.fixture(scope="module")
def glance(tmp_path_factory):
    world = load_world(HOSPITAL)
    return world, plan_by_hand(world, "queuing", SENTENCE.format(verb="glance"), QUEUE,
                               tmp_path_factory.mktemp("glance") / "b")


def test_a_glance_is_one_short_look_and_holds_on_a_faithful_run(glance):
    world, run = glance
    claim = _look(run.report)
    assert claim.seconds == GLANCE_SECONDS and "glance" in claim.asked, claim
    surprised = _surprised(run)
    assert float(surprised.get("beh_duration")) == GLANCE_REACTION and surprised.get("only_once") == "true"
    report = run.run(120.0)
    assert _look(report).status == "holds", _look(report).evidence
    # the same run, checked as a stare, is not one: they looked once and went on queuing
    stare = replace(claim, seconds=None)
    planned = replace(run.report, groups=tuple(replace(g, claims=tuple(stare if c.kind == "robot_look" else c
                                                                       for c in g.claims))
                                               for g in run.report.groups))
    assert _look(run.check(planned, world)).status == "fails"


def test_a_stare_lasts_while_the_robot_is_near(tmp_path):
    world = load_world(HOSPITAL)
    run = plan_by_hand(world, "queuing", SENTENCE.format(verb="stare"), QUEUE, tmp_path / "b")
    claim = _look(run.report)
    assert claim.seconds is None and "most of the time" in claim.asked, claim
    assert _surprised(run).get("only_once") == "false"
    report = run.run(120.0)
    assert _look(report).status == "holds", _look(report).evidence


def test_people_who_only_glance_turn_to_it_once_and_those_who_stare_keep_facing_it(tmp_path):
    world = load_world(HOSPITAL)
    corridor = (DraftGroup("cleaner", 2, "main_corridor", DraftNode("LookAtRobot", {})),)
    glancers = plan_by_hand(world, "normal", "Two cleaners glance at the robot as it passes through the main "
                            "corridor.", corridor, tmp_path / "glance")
    assert _surprised(glancers).get("only_once") == "true"
    assert _look(glancers.report).seconds == GLANCE_SECONDS
    starers = plan_by_hand(world, "normal", "Two cleaners stare at the robot as it passes through the main "
                           "corridor.", corridor, tmp_path / "stare")
    xml = (starers.bundle / starers.op.agents[0].tree).read_text(encoding="utf-8")
    assert "<LookAtRobot" in xml and _look(starers.report).seconds is None
