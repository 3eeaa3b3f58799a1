"""People the sentence puts in a room to react to the robot react only if it comes by: a robot whose
route the sentence fixes elsewhere looks into their room on its way (planning.plan_operational)."""

from __future__ import annotations

import numpy as np
import shapely

from grove_tui.generation.draft import Draft, DraftGroup, DraftNode
from grove_tui.generation.planning import plan_operational
from grove_tui.generation.postprocess import postprocess
from grove_tui.generation.presets import load_preset
from grove_tui.generation.rois import select_rois
from grove_tui.language.reading import read_prompt
from grove_tui.navigation.grid import build_grid

PROMPT = "the robot drives from the pharmacy to the cafeteria while two patients in ward C stare at it"


def plan(world, prompt, groups):
    preset = load_preset("normal")
    reading = read_prompt(prompt, world)
    grid = build_grid(world)
    post = postprocess(world, grid, preset, Draft(tuple(groups)), select_rois(world, preset, reading), 0, reading,
                       ("Sequence", "GoTo", "Wait", "LookAtRobot"))
    return plan_operational(world, grid, preset, post, 0, reading=reading)


def enters(path, zone) -> bool:
    return shapely.LineString(path).intersects(zone.polygon.buffer(-0.5))


def test_a_robot_whose_route_misses_the_room_of_the_people_reacting_looks_in(hospital):
    ward = hospital.zone("ward_c")
    op = plan(hospital, PROMPT, [DraftGroup("patients", 2, "ward_c", DraftNode("LookAtRobot"))])
    robot = op.robot
    assert robot is not None and enters(robot.path, ward)
    assert hospital.zone("pharmacy").polygon.buffer(0.3).contains(shapely.Point(robot.start))
    assert hospital.zone("cafeteria").polygon.buffer(0.3).contains(shapely.Point(robot.goal))
    assert any("passes through ward_c" in n for n in op.notes)
    assert not any("no free floor beside the robot's route" in n for n in op.notes)
    # the patients stand where it passes: within sight of its route, in their ward
    route = shapely.LineString(robot.path)
    for agent in op.agents:
        assert ward.polygon.buffer(0.3).contains(shapely.Point(agent.start))
        assert route.distance(shapely.Point(agent.start)) < 9.0


def test_a_room_the_route_passes_is_left_as_it_is(hospital):
    op = plan(hospital, "the robot crosses from reception to the staff room; visitors in the main waiting room "
                        "look at it", [DraftGroup("visitors", 3, "main_waiting_room", DraftNode("LookAtRobot"))])
    assert not any("passes through" in n for n in op.notes)
    assert np.isfinite(np.asarray(op.robot.path)).all()
