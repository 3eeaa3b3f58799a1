"""Issue 19: an evacuation uses every exit the prompt allows, each person through their nearest."""

from __future__ import annotations


from grove_tui.bt.format.xml import validate_document
from grove_tui.generation.draft import Draft, DraftGroup, DraftNode
from grove_tui.generation.planning import plan_operational
from grove_tui.generation.postprocess import postprocess
from grove_tui.generation.presets import load_preset
from grove_tui.generation.rois import select_rois
from grove_tui.language.reading import read_prompt
from grove_tui.navigation.grid import build_grid
from grove_tui.navigation.theta_star import ThetaStarPlanner
from grove_tui.simulation.simulation import Simulation
from grove_tui.world import parse_world

TWO_EXITS = """
name: two_exit_hall
description: A 24 m x 10 m hall with an exit door in the middle of each end wall.
zones:
  - name: hall
    type: hall
    description: Open hall.
    boundary: [[0, 0], [24, 0], [24, 10], [0, 10]]
    doors:
      - {name: west_exit, position: [0, 5], width: 1.6, leads_to: outside, exit: true}
      - {name: east_exit, position: [24, 5], width: 1.6, leads_to: outside, exit: true}
"""


def evacuation(prompt: str, count: int):
    world, problems = parse_world(TWO_EXITS, "two_exits.yaml")
    assert not problems
    grid = build_grid(world)
    preset = load_preset("emergency")
    # The small model names one exit for everyone; the prompt allows both.
    draft = Draft((DraftGroup("people", count, "hall", DraftNode("FollowVelocityField", {"exit": "east_exit"})),))
    reading = read_prompt(prompt, world)
    post = postprocess(world, grid, preset, draft, select_rois(world, preset, reading), 0, reading,
                       ("Sequence", "FollowVelocityField"))
    op = plan_operational(world, grid, preset, post, 0)
    return world, grid, post, op


def test_each_person_takes_their_nearest_exit_and_both_exits_are_used():
    world, grid, post, op = evacuation("Thirty people evacuate the hall", 30)
    assert sorted(post.exits) == ["east_exit", "west_exit"]
    exits = {a.id: a.exit for a in post.agents}
    for a in post.agents:
        nearer = "west_exit" if a.start[0] < 12.0 else "east_exit"
        if abs(a.start[0] - 12.0) > 1.0:  # clear of the middle, where the two walks tie
            assert a.exit == nearer, (a.id, a.start, a.exit)
    assert set(exits.values()) == {"east_exit", "west_exit"}
    # one field per exit the group uses, each leading to its own door
    assert {f.exit for f in op.fields.values()} == {world.find("west_exit").position, world.find("east_exit").position}
    documents = [validate_document(op.trees[a.tree]) for a in op.agents]
    for spec, document in zip(op.agents, documents):
        node = next(el for el in document.nodes() if el.id == "FollowVelocityField")
        assert node.get("exit") == exits[spec.id]
    sim = Simulation.build(op.agents, documents, world=world, grid=grid, planner=ThetaStarPlanner(grid),
                           walls=world.walls(), fields=op.fields, seed=0)
    while sim.time < 90.0 and sim.crowd.active[: len(op.agents)].any():
        sim.step()
    left = {e.agent_id: e.detail for e in sim.events if e.kind == "evacuated"}
    assert len(left) == 30, f"{30 - len(left)} people still inside after 90 s"
    assert set(left.values()) == {"east_exit", "west_exit"}  # both doors were used
    assert all(left[i] == exits[i] for i in left)  # everyone through the exit chosen for them


def test_an_exit_the_prompt_names_is_the_only_one_used():
    _world, _grid, post, op = evacuation("Thirty people evacuate the hall through the west exit", 30)
    assert post.exits == ["west_exit"]
    assert {a.exit for a in post.agents} == {"west_exit"}
    assert len(op.fields) == 1
