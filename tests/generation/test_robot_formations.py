"""Issue 21 item 13: the robot's planner treats queues and conversation circles as obstacles.

Headless, on the clinic world: the trees come from post-processing, the queue's geometry from the
runtime's own coordination code on the grid, the robot's path from Theta*, and the simulation checks
that the predicted queue is where the simulated people really stand.
"""

from __future__ import annotations

import numpy as np
from helpers.clinic import QUEUE, make_result

from grove_tui.generation.draft import Draft, DraftGroup, DraftNode
from grove_tui.generation.formations import (
    PASSING_MARGIN,
    formation_distance,
    nearest_formation_gap,
    predict_formations,
)
from grove_tui.generation.planning import RobotRequest, plan_operational
from grove_tui.generation.postprocess import postprocess
from grove_tui.generation.presets import load_preset
from grove_tui.generation.rois import select_rois
from grove_tui.language.reading import read_prompt
from grove_tui.navigation.grid import build_grid
from grove_tui.navigation.theta_star import ThetaStarPlanner
from grove_tui.scenario.bundle import load_bundle, write_bundle
from grove_tui.scenario.model import RobotSpec
from grove_tui.simulation.simulation import Simulation

QUEUE_PROMPT = "six patients queue at the pharmacy counter"
CHAT_PROMPT = "four friends chat in the cafeteria"
# The robot's body plus the margin it keeps, less one grid cell: Theta* corners are cell centres.
CLEARANCE = RobotSpec((0.0, 0.0), (0.0, 0.0)).radius + PASSING_MARGIN - 0.1


def post_processed(clinic, grid, preset_name, prompt, group):
    preset = load_preset(preset_name)
    reading = read_prompt(prompt, clinic)
    selection = select_rois(clinic, preset, reading)
    return preset, postprocess(clinic, grid, preset, Draft((group,)), selection, 0, reading,
                               ("Sequence", "GoTo", "Queue", "Converse"))


def robot_across(clinic, grid, preset, post, centre, half_width=4.0):
    request = RobotRequest(start=(centre[0] - half_width, centre[1]), goal=(centre[0] + half_width, centre[1]))
    return plan_operational(clinic, grid, preset, post, 0, request)


def test_the_robots_path_goes_around_the_queue_not_through_it(clinic, grid):
    preset, post = post_processed(clinic, grid, "queuing", QUEUE_PROMPT, DraftGroup("patients", 6, "pharmacy", QUEUE))
    formations = predict_formations(clinic, grid, [a.document for a in post.agents], post.goals)
    assert [(f.kind, f.name, len(f.line)) for f in formations] == [("queue", "pharmacy_counter", 6)]
    middle = formations[0].line[3]
    op = robot_across(clinic, grid, preset, post, middle)
    path = list(op.robot.path)
    assert nearest_formation_gap(formations, [path[0], path[-1]]) == 0.0, "the straight line runs through the queue"
    assert nearest_formation_gap(formations, path) >= CLEARANCE
    planner = ThetaStarPlanner(grid)
    assert all(planner.segment_is_free(a[0], a[1], b[0], b[1]) for a, b in zip(path, path[1:]))
    assert not [note for note in op.notes if "passes close" in note]


def test_the_robot_chosen_across_the_crowd_keeps_clear_of_the_queue_and_the_served(clinic, grid):
    preset, post = post_processed(clinic, grid, "queuing", QUEUE_PROMPT, DraftGroup("patients", 6, "pharmacy", QUEUE))
    formations = predict_formations(clinic, grid, [a.document for a in post.agents], post.goals)
    assert len(formations[0].spots) == 6, "the trees end with the queue: every served person stands aside"
    op = plan_operational(clinic, grid, preset, post, 0)
    assert nearest_formation_gap(formations, list(op.robot.path)) >= CLEARANCE


def test_the_robots_path_goes_around_a_conversation_circle(clinic, grid):
    preset, post = post_processed(clinic, grid, "normal", CHAT_PROMPT,
                                  DraftGroup("friends", 4, "lobby", DraftNode("Converse", {"target": "cafeteria"})))
    formations = predict_formations(clinic, grid, [a.document for a in post.agents], post.goals)
    assert [f.kind for f in formations] == ["conversation"]
    centre = formations[0].line[0]
    op = robot_across(clinic, grid, preset, post, centre)
    path = list(op.robot.path)
    assert nearest_formation_gap(formations, [path[0], path[-1]]) == 0.0
    assert nearest_formation_gap(formations, path) >= CLEARANCE


def test_a_robot_sent_into_the_queue_still_gets_there(clinic, grid):
    preset, post = post_processed(clinic, grid, "queuing", QUEUE_PROMPT, DraftGroup("patients", 6, "pharmacy", QUEUE))
    op = plan_operational(clinic, grid, preset, post, 0, RobotRequest(start="main_entrance", goal="pharmacy_counter"))
    assert op.robot.path[-1] == op.robot.goal


def test_the_predicted_queue_is_where_the_simulated_people_stand(clinic, tmp_path):
    result = make_result(clinic, "queuing", QUEUE_PROMPT, [DraftGroup("patients", 6, "pharmacy", QUEUE)])
    bundle = write_bundle(result, tmp_path / "bundle")
    scenario, *_ = load_bundle(bundle)
    formations = predict_formations(clinic, result.grid, list(result.trees.values()))
    sim = Simulation.from_scenario(scenario, bundle, world=clinic)
    sim.run(40.0)
    frame = sim.frame()
    queued = [i for i, status in enumerate(frame.status) if "queue" in status or "served" in status]
    assert len(queued) == 6
    # Bodies stand where the prediction put them, give or take the push of their neighbours.
    assert formation_distance(formations[0], np.asarray(frame.pos)[queued]).max() < 0.25


NARROW = """
name: narrow
description: A corridor with a ticket counter halfway along its north wall.
zones:
  - name: corridor
    type: corridor
    description: A long narrow corridor.
    boundary: [[0, 0], [16, 0], [16, 1.8], [0, 1.8]]
    entities:
      - {name: ticket_counter, type: counter, footprint: [[7.5, 1.5], [8.5, 1.5], [8.5, 1.8], [7.5, 1.8]], interaction_point: [8, 1.0]}
"""


def test_with_no_way_around_the_robot_passes_the_queue_and_the_report_says_so(tmp_path):
    from grove_tui.world import load_world

    (tmp_path / "narrow.yaml").write_text(NARROW, encoding="utf-8")
    narrow = load_world(tmp_path / "narrow.yaml")
    grid = build_grid(narrow)
    queue = DraftNode("Sequence", {}, (DraftNode("GoTo", {"target": "ticket_counter"}),
                                       DraftNode("Queue", {"service_point": "ticket_counter"})))
    preset, post = post_processed(narrow, grid, "queuing", "five people queue at the ticket counter",
                                  DraftGroup("people", 5, "corridor", queue))
    op = plan_operational(narrow, grid, preset, post, 0, RobotRequest(start=(0.8, 0.9), goal=(15.2, 0.9)))
    assert op.robot.path[-1] == (15.2, 0.9), "the robot still gets to its goal"
    assert [note for note in op.notes if "passes close" in note] == [
        "the robot's path passes close to the queue at ticket_counter (5 places): there is no way around"]
