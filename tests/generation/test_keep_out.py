"""A place the sentence rules out ("..., avoiding the main waiting room"): the group's waypoints go round
it when there is a way round; when there is none they go through, and a note says so."""

from __future__ import annotations

import pytest
import shapely

from grove_tui.errors import PlanningError
from grove_tui.generation.draft import Draft, DraftGroup, DraftNode
from grove_tui.generation.keep_out import keep_out_planner
from grove_tui.generation.planning import goals_from_tree, plan_operational
from grove_tui.generation.postprocess import postprocess
from grove_tui.generation.presets import load_preset
from grove_tui.generation.rois import select_rois
from grove_tui.language.reading import read_prompt
from grove_tui.navigation.grid import build_grid
from grove_tui.navigation.theta_star import ThetaStarPlanner


def crosses(path, zone) -> bool:
    return shapely.LineString(path).intersects(zone.polygon.buffer(-0.3))


def test_the_plan_goes_round_a_room_ruled_out(hospital):
    grid = build_grid(hospital)
    a, b = hospital.zone("radiology").centroid, hospital.zone("cafeteria").centroid
    waiting = hospital.zone("main_waiting_room")
    assert crosses(ThetaStarPlanner(grid).plan(a, b), waiting)  # the shortest way is through it
    around = keep_out_planner(hospital, grid, ["main_waiting_room"])
    assert around is not None and not crosses(around.plan(a, b), waiting)


def test_no_way_round_is_a_planning_error_the_caller_can_take(clinic, grid):
    around = keep_out_planner(clinic, grid, ["corridor"])
    with pytest.raises(PlanningError):
        around.plan(clinic.zone("lobby").centroid, clinic.zone("cafeteria").centroid)


def plan(world, grid, prompt, groups):
    preset = load_preset("normal")
    reading = read_prompt(prompt, world)
    post = postprocess(world, grid, preset, Draft(tuple(groups)), select_rois(world, preset, reading), 0, reading,
                       ("Sequence", "GoTo", "Wait"))
    return post, plan_operational(world, grid, preset, post, 0, reading=reading)


def test_every_member_is_planned_round_it(hospital):
    grid = build_grid(hospital)
    _, op = plan(hospital, grid, "Three porters walk from radiology to the cafeteria, avoiding the main waiting room",
                 [DraftGroup("porters", 3, "radiology", DraftNode("GoTo", {"target": "cafeteria"}))])
    waiting = hospital.zone("main_waiting_room")
    for agent in op.agents:
        assert not crosses([agent.start, *goals_from_tree(op.trees[agent.tree])], waiting)


def test_with_no_way_round_they_go_through_and_the_notes_say_so(clinic, grid):
    _, op = plan(clinic, grid, "Four visitors walk from the lobby to the cafeteria, avoiding the corridor",
                 [DraftGroup("visitors", 4, "lobby", DraftNode("GoTo", {"target": "cafeteria"}))])
    assert len(op.agents) == 4
    assert any("no way round corridor" in n for n in op.notes)
