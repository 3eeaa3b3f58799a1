"""The exit the robot leads people to, where the sentence names none in particular, is the nearest that fits.
"The robot leads a family to the exit" (airport): the robot drove 98 m to emergency_exit_east, an exit picked
by its words alone. Now of the exits that fit, the robot and the family it leads go to the one nearest by
planned path from where they set off, and the report says which others fit. Planned from hand-written drafts
(no model) over three worlds and a real simulation."""

from __future__ import annotations

import math

import pytest
from helpers.planned_run import plan_by_hand

from grove_tui.generation.draft import DraftGroup, DraftNode
from grove_tui.generation.led_exit import fitting_exits
from grove_tui.language.reading import read_prompt
from grove_tui.navigation.grid import build_grid
from grove_tui.navigation.theta_star import ThetaStarPlanner
from grove_tui.world import load_world

SENTENCE = "The robot leads a family to the exit"


def _length(path):
    return sum(math.dist(a, b) for a, b in zip(path, path[1:]))


@pytest.mark.parametrize("world_name, preset, zone", [
    ("airport", "emergency", "security_checkpoint"),
    ("hospital", "normal", "entrance_lobby"),
    ("station", "normal", "ticket_hall"),
])
def test_the_robot_leads_them_to_the_nearest_exit_that_fits(tmp_path, world_name, preset, zone):
    world = load_world(f"worlds/{world_name}.yaml")
    fit = fitting_exits(world, read_prompt(SENTENCE, world))
    assert len(fit) > 1, fit
    run = plan_by_hand(world, preset, SENTENCE, (DraftGroup("family", 4, zone, DraftNode("Wait", {"duration": 5.0})),),
                       tmp_path / "b")
    robot = run.op.robot
    planner = ThetaStarPlanner(build_grid(world))
    exits = {d.name: d for d in world.exits() if d.name in fit}
    lengths = {}
    for name, door in exits.items():
        try:
            lengths[name] = _length([tuple(p) for p in planner.plan(robot.start, door.inward_point(0.6))])
        except Exception:
            continue
    nearest = min(lengths, key=lengths.get)
    reach = next(c for c in run.report.robot.claims if c.kind == "robot_reach")
    assert reach.place == nearest, (reach.place, lengths)
    family = next(c for g in run.report.groups for c in g.claims if c.kind == "reach")
    assert family.place == nearest
    # the others that fit are still said
    assert any(nearest in u and "fit too" in u or "?" in u for u in run.report.unsure), run.report.unsure


def test_a_real_run_leads_the_family_to_the_nearest_exit(tmp_path):
    world = load_world("worlds/airport.yaml")
    run = plan_by_hand(world, "emergency", SENTENCE,
                       (DraftGroup("family", 4, "security_checkpoint", DraftNode("Wait", {"duration": 5.0})),),
                       tmp_path / "b")
    assert _length(run.op.robot.path) < 40.0, run.op.robot.path
    report = run.run(90.0)
    reach = next(c for c in report.robot.claims if c.kind == "robot_reach")
    assert reach.status == "holds", reach.evidence
    follow = next(c for g in report.groups for c in g.claims if c.kind == "robot_follow")
    assert follow.status == "holds", follow.evidence
