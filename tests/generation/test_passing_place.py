"""People whose look is tied to the robot passing stand where it passes, and it passes all of them.

"Visitors look up as the robot passes the ticket desk" (station, museum, aquarium): the visitors only react and
the sentence puts them nowhere; they were stood beside the robot's route a third of the way along it, near its
start, and looked long before it came by the desk. They now stand beside the route where it passes the desk
(generation/passing_place.py). "Ten patients queue at the pharmacy and look at the robot as it passes": the
robot's way was aimed at the head of the queue (every queuer counted at the counter); it now passes within
PASS_NEAR of every place in the line (generation/queue_pass.py). Planned from hand-written drafts (no model),
and a real simulation."""

from __future__ import annotations

import math

import pytest
from helpers.planned_run import NODES, plan_by_hand

from grove_tui.generation.draft import Draft, DraftGroup, DraftNode
from grove_tui.generation.formations import predict_formations
from grove_tui.analysis.outcomes import PASS_BY
from grove_tui.generation.passing_reactors import widest_gap
from grove_tui.generation.planning import plan_operational
from grove_tui.generation.postprocess import postprocess
from grove_tui.generation.presets import load_preset
from grove_tui.generation.rois import select_rois
from grove_tui.language.reading import read_prompt
from grove_tui.navigation.grid import build_grid
from grove_tui.world import load_world

VISITORS = "Visitors look up as the robot passes the ticket desk."
DESKS = [("station", "ticket_hall", "ticket_office"), ("museum", "entrance_hall", "ticket_desk"),
         ("eval/understanding/worlds/aquarium.yaml", None, "ticket_desk")]


def _look(report):
    return next(c for g in report.groups for c in g.claims if c.kind == "robot_look")


@pytest.mark.parametrize("world_name, spawn, desk", DESKS)
def test_they_stand_where_the_robot_passes_the_desk(tmp_path, world_name, spawn, desk):
    world = load_world(world_name)
    spawn = spawn or world.zones[0].name
    run = plan_by_hand(world, "normal", VISITORS, (DraftGroup("visitors", 3, spawn, DraftNode("LookAtRobot", {})),),
                       tmp_path / "b")
    point = world.find(desk).interaction_point
    look = _look(run.report)
    assert look.moment == "pass" and look.place == desk, look
    route = [tuple(p) for p in run.op.robot.path]
    assert min(math.dist(p, point) for p in route) < 1.0, route  # the robot's way passes the desk
    for a in run.op.agents:  # each visitor stands beside the desk, not at the route's start
        assert math.dist(a.start, point) <= 4.5, (a.start, point, run.op.notes)


def test_they_look_up_as_it_passes_the_desk_on_the_run(tmp_path):
    world = load_world("museum")
    run = plan_by_hand(world, "normal", VISITORS, (DraftGroup("visitors", 3, "entrance_hall",
                                                              DraftNode("LookAtRobot", {})),), tmp_path / "b")
    look = _look(run.run(45.0))
    assert look.status == "holds", look.evidence


@pytest.mark.parametrize("world_name, count, counter, words, spawn", [
    ("hospital", 14, "pharmacy", "the pharmacy", "main_corridor"),
    ("airport", 12, "check_in_counter_a", "check-in counter A", None),
])
def test_the_robot_passes_the_whole_queue(world_name, count, counter, words, spawn):
    """Every place in the line within PASS_BY of the robot's way, where the look is cued and checked (before:
    the back of the line 9.5 m and 6.3 m from it)."""
    world = load_world(world_name)
    preset = load_preset("normal")
    grid = build_grid(world)
    reading = read_prompt(f"{count} patients queue at {words} and look at the robot as it passes.", world)
    tree = DraftNode("Sequence", {}, (DraftNode("GoTo", {"target": counter}),
                                      DraftNode("Queue", {"service_point": counter})))
    group = DraftGroup("patients", count, spawn or world.zones[0].name, tree)
    post = postprocess(world, grid, preset, Draft((group,)), select_rois(world, preset, reading), 0, reading, NODES)
    queue, = [f for f in predict_formations(world, grid, [a.document for a in post.agents if a.document], post.goals)
              if f.kind == "queue"]
    assert len(queue.line) == count
    op = plan_operational(world, grid, preset, post, 0, reading=reading)
    assert widest_gap(op.robot.path, queue.line) <= PASS_BY, (op.robot.path, queue.line)


def test_a_look_as_it_passes_them_is_cued_where_it_is_checked(tmp_path):
    """Cued at PASS_AT (4 m), queueing patients the robot passed at 4.2 m never turned (2/6 looked); the cue is
    PASS_BY, the reach the look is checked in."""
    tree = DraftNode("Sequence", {}, (DraftNode("GoTo", {"target": "pharmacy"}),
                                      DraftNode("Queue", {"service_point": "pharmacy"})))
    run = plan_by_hand(load_world("hospital"), "normal", "Six patients queue at the pharmacy and look at the robot "
                       "as it passes.", (DraftGroup("patients", 6, "main_corridor", tree),), tmp_path / "b")
    xml = (run.bundle / run.op.agents[0].tree).read_text(encoding="utf-8")
    assert f'threshold="{PASS_BY:g}' in xml and 'threshold="4' not in xml, xml


GUARDS = "Two guards turn to watch as the robot passes the information desk on its way to the cafe."


@pytest.mark.parametrize("world_name, sentence, spawn", [
    ("museum", GUARDS, "entrance_hall"),
    ("museum", VISITORS, "entrance_hall"),
    ("station", VISITORS, "ticket_hall"),
])
def test_they_stand_beside_the_route_not_on_a_later_leg_of_it(tmp_path, world_name, sentence, spawn):
    """The band a reactor stands in is from the whole route: a guard stood 2 m from the point of the route by the
    desk was 0.2 m from the leg before it, and the robot came within 0.5 m of him."""
    world = load_world(world_name)
    run = plan_by_hand(world, "normal", sentence, (DraftGroup("guards", 2, spawn, DraftNode("LookAtRobot", {})),),
                       tmp_path / "b")
    path = run.op.robot.path
    for a in run.op.agents:
        assert widest_gap(path, [a.start]) >= 2.0 - 0.05, (a.start, path)
