"""A crowd the robot guides ("the robot guides a group of eight tourists from the entrance hall to the
Egyptian gallery") walks behind it as a crowd: the last of them 5 m back, but with the others. The
follow check takes a member within 2 m of one who is near the robot as following (as it does for people
following a person); people standing where the robot set off are not following it."""

from __future__ import annotations

from dataclasses import replace

import pytest
from helpers.planned_run import plan_by_hand

from grove_tui.generation.draft import DraftGroup, DraftNode
from grove_tui.scenario.report import FAILS, HOLDS
from grove_tui.world import load_world

SENTENCE = ("The robot guides a group of eight tourists from the entrance hall to the egyptian gallery "
            "while four visitors wait in the entrance hall.")


@pytest.fixture(scope="module")
def guided(tmp_path_factory):
    museum = load_world("museum")
    # the model's trees had no action (as it wrote them for this sentence): the reading's trees are played
    idle = DraftNode("IsRobotClose", {})
    run = plan_by_hand(museum, "normal", SENTENCE, (DraftGroup("tourists", 8, "entrance_hall", idle),
                                                    DraftGroup("visitors", 4, "entrance_hall", idle)),
                       tmp_path_factory.mktemp("guided") / "bundle")
    checked = run.run(_follow(run.report.groups[0]).needs_seconds or 60.0)
    return museum, run, checked


def _follow(group):
    return next(c for c in group.claims if c.kind == "robot_follow")


def test_the_crowd_behind_the_robot_follows_it(guided):
    _, _, checked = guided
    follow = _follow(checked.groups[0])
    assert follow.status == HOLDS and follow.evidence.startswith("8/8"), follow.evidence


def test_people_standing_where_it_set_off_do_not_follow_it(guided):
    museum, run, _ = guided
    tourists, visitors = run.report.groups
    # the tourists' follow claim said of the visitors, who wait in the hall as the robot leaves
    moved = replace(run.report, groups=(replace(tourists, members=visitors.members),))
    follow = _follow(run.check(moved, museum).groups[0])
    assert follow.status == FAILS, follow.evidence
