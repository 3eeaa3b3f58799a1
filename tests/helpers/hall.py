"""A 20 m x 12 m hall for behavior-tree scenario tests: a service counter on the west wall (people stand
at (2.2, 6)), a fountain in the north middle, an exit door (2 m) in the middle of the east wall.
The `hall` fixture (world, grid, planner) is in tests/conftest.py."""

from __future__ import annotations

from grove_tui.bt.format.xml import parse_tree_text
from grove_tui.scenario.model import AgentSpec
from grove_tui.simulation.simulation import Simulation

HALL = """
name: bt_test_hall
description: A 20 m x 12 m hall with a service counter on the west wall and an exit door on the east wall.
zones:
  - name: hall
    type: hall
    description: Open hall.
    boundary: [[0, 0], [20, 0], [20, 12], [0, 12]]
    doors:
      - {name: exit_door, position: [20, 6], width: 2.0, leads_to: outside, exit: true}
    entities:
      - name: counter
        type: counter
        description: Service counter.
        footprint: [[0.5, 4.5], [1.5, 4.5], [1.5, 7.5], [0.5, 7.5]]
        interaction_point: [2.2, 6]
      - name: fountain
        type: fountain
        description: A fountain in the north middle of the hall.
        footprint: [[9, 9], [11, 9], [11, 11], [9, 11]]
        interaction_point: [10, 8.4]
"""


def tree_xml(body: str) -> str:
    return f'<root BTCPP_format="4" main_tree_to_execute="T"><BehaviorTree ID="T">{body}</BehaviorTree></root>'


def agent(i: int, start, *, group=-1, radius=0.35, max_vel=1.0, behavior="Regular", goals=()):
    return AgentSpec(id=i, group=group, start=start, goals=goals, zone="hall", tree=f"trees/agent_{i}.xml",
                     radius=radius, max_vel=max_vel, behavior=behavior)


def simulate(hall, agents, bodies, robot=None, fields=None):
    world, grid, planner = hall
    documents = [parse_tree_text(tree_xml(b), f"agent_{a.id}.xml") for a, b in zip(agents, bodies)]
    return Simulation.build(agents, documents, world=world, grid=grid, planner=planner, walls=world.walls(),
                            robot=robot, fields=fields, seed=7)


def run_until(sim, predicate, limit: float):
    while sim.time < limit:
        sim.step()
        if predicate():
            return True
    return False


def running(sim, agent_id: int, node_id: str) -> bool:
    return any(name.split(" ")[0] == node_id and status == "RUNNING" for _, name, status in sim.tree_status(agent_id))
