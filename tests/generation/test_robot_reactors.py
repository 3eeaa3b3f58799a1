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
from grove_tui.generation.pipeline import GenerationResult
from grove_tui.navigation.grid import build_grid
from grove_tui.scenario.bundle import load_bundle, write_bundle
from grove_tui.scenario.model import Scenario
from grove_tui.simulation.simulation import Simulation
from grove_tui.world import load_world

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


def test_the_person_the_robot_follows_walks_at_a_pace_it_can_keep(hospital):
    prompt = "the robot follows a nurse from the pharmacy to radiology"
    op = plan(hospital, prompt, [DraftGroup("nurse", 1, "pharmacy", DraftNode("GoTo", {"target": "radiology"}))])
    robot = op.robot
    assert robot.task == "follow" and robot.follows
    followed = [a for a in op.agents if a.id in robot.follows]
    assert followed and all(a.max_vel <= 0.9 * robot.max_vel + 1e-9 for a in followed)


def test_a_hurrying_person_keeps_their_pace(hospital):
    prompt = "the robot follows a nurse who hurries from the pharmacy to radiology"
    op = plan(hospital, prompt, [DraftGroup("nurse", 1, "pharmacy", DraftNode("GoTo", {"target": "radiology"}))])
    followed = [a for a in op.agents if a.id in op.robot.follows]
    assert followed and all(a.max_vel > op.robot.max_vel for a in followed)


GUIDED = "The robot guides a group of eight tourists from the entrance hall to the egyptian gallery"


def test_people_the_robot_guides_start_behind_it_and_it_leads_at_its_pace(tmp_path):
    # placed on its route 9 m ahead, the eight crowded the robot's front and it crawled at 0.2 m/s for
    # its first 20 s; behind its start, it leads at its pace and they still keep up with it
    museum = load_world("museum")
    prompt_groups = [DraftGroup("tourists", 8, "entrance_hall", DraftNode("Wait", {"wait_time": 5.0}))]
    preset = load_preset("normal")
    reading = read_prompt(GUIDED, museum)
    grid = build_grid(museum)
    post = postprocess(museum, grid, preset, Draft(tuple(prompt_groups)), select_rois(museum, preset, reading), 0,
                       reading, ("Sequence", "GoTo", "Wait"))
    op = plan_operational(museum, grid, preset, post, 0, reading=reading)
    robot = op.robot
    path = np.asarray(robot.path)
    heading = (path[1] - path[0]) / np.hypot(*(path[1] - path[0]))
    starts = np.asarray([a.start for a in op.agents])
    assert len(starts) == 8 and (((starts - path[0]) @ heading) <= 0.0).all(), "none ahead of it on its way"
    scenario = Scenario(world=str(museum.source), preset=preset.name, prompt=GUIDED, seed=0, models={"bt": "hand"},
                        agents=tuple(op.agents), robot=robot, fields={fid: f"fields/{fid}.npz" for fid in op.fields})
    bundle = write_bundle(GenerationResult(scenario, op.trees, op.fields, grid, {"stages": {}, "notes": post.notes}),
                          tmp_path / "bundle")
    sim = Simulation.from_scenario(load_bundle(bundle)[0], bundle, world=museum)
    frames = []
    sim.run(20.0, on_frame=frames.append)
    route = np.asarray([f.robot[:2] for f in frames if f.robot is not None])
    assert np.hypot(*np.diff(route, axis=0).T).sum() / 20.0 >= 0.5
    # they follow it: at the end of those 20 s most are within a few metres of it
    last = frames[-1]
    near = np.hypot(last.pos[:, 0] - last.robot[0], last.pos[:, 1] - last.robot[1]) <= 5.0
    assert near.sum() >= 6
