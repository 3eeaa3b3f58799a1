"""People who follow someone ("ten tourists follow their guide to the gallery"): the person followed is in
the scene, the followers walk behind them (FollowAgent on the guide's id) and then on to the place, the
guide walks at their pace, and the leg after following is planned from where the run leaves them."""

from __future__ import annotations

import pytest
from grove_tui.generation.draft import Draft, DraftGroup, DraftNode
from grove_tui.generation.planning import plan_operational
from grove_tui.generation.postprocess import postprocess
from grove_tui.generation.presets import load_preset
from grove_tui.generation.reconcile import LEADER_PACE, with_followed_person
from grove_tui.generation.rois import select_rois
from grove_tui.language.reading import read_prompt
from grove_tui.navigation.grid import build_grid
from grove_tui.world import load_world


def generate(world, prompt, drafts=()):
    preset = load_preset("normal")
    reading = with_followed_person(read_prompt(prompt, world), world)
    grid = build_grid(world)
    post = postprocess(world, grid, preset, Draft(tuple(drafts)), select_rois(world, preset, reading), 0, reading,
                       ("Sequence", "GoTo", "Wait", "FollowAgent", "JoinGroup"))
    return reading, post, plan_operational(world, grid, preset, post, 0, reading=reading)


@pytest.mark.parametrize("world_name, prompt, followers, leader", [
    ("museum", "A group of ten tourists follows their guide from the entrance hall to the Egyptian gallery",
     "tourist", "guide"),
    ("hospital", "Six medical students follow the senior doctor from the entrance lobby to ward C", "student",
     "doctor"),
    ("office", "Two assistants follow the manager from reception to the boardroom", "assistant", "manager"),
])
def test_followers_walk_behind_the_person_they_follow_who_is_in_the_scene(world_name, prompt, followers, leader):
    world = load_world(world_name)
    reading, post, op = generate(world, prompt)
    by_label = {g.label: g for g in post.groups}
    assert set(by_label) == {followers, leader}  # the one followed is there, though only named as followed
    guide_id = by_label[leader].member_ids[0]
    for member in by_label[followers].member_ids:
        nodes = {n.id: n for n in op.trees[f"trees/agent_{member}.xml"].nodes()}
        assert nodes["FollowAgent"].get("target_agent_id") == str(guide_id)
        # then on to the place, from wherever following left them: no waypoints planned beforehand
        assert nodes["GoTo"].get("waypoints") == ""
    assert by_label[leader].speed_factor == pytest.approx(LEADER_PACE)
    assert all(n.id != "FollowAgent" for n in op.trees[f"trees/agent_{guide_id}.xml"].nodes())


@pytest.mark.parametrize("prompt", [
    "Ten tourists follow their guide as she hurries from the entrance hall to the Egyptian gallery",
    "A guide hurries from the entrance hall to the Egyptian gallery and ten tourists follow her",
])
def test_a_hurrying_leader_keeps_its_pace(prompt):
    _, post, _ = generate(load_world("museum"), prompt)
    guide = next(g for g in post.groups if g.label == "guide")
    assert guide.speed_factor > 1.0


@pytest.mark.parametrize("world_name, prompt, followers, leader", [
    ("museum", "Fifteen pupils follow their teacher through the Egyptian gallery", "pupil", "teacher"),
    ("hospital", "Four students follow the consultant through the main waiting room", "student", "consultant"),
])
def test_followers_of_a_walk_through_follow_it_all_and_end_where_their_leader_ends(world_name, prompt, followers,
                                                                                    leader):
    world = load_world(world_name)
    _, post, op = generate(world, prompt)
    by_label = {g.label: g for g in post.groups}
    guide = op.trees[f"trees/agent_{by_label[leader].member_ids[0]}.xml"]
    guide_goals = [n.get("target") for n in guide.nodes() if n.id == "GoTo"]
    assert guide_goals
    for member in by_label[followers].member_ids:
        nodes = list(op.trees[f"trees/agent_{member}.xml"].nodes())
        goals = [n.get("target") for n in nodes if n.id == "GoTo"]
        assert goals[0] == guide_goals[-1] and not set(goals[1:]) & set(guide_goals)  # never back
        follow = next(n for n in nodes if n.id == "FollowAgent")
        assert float(follow.get("duration")) >= 30.0  # the leader's whole walk, from where they start
