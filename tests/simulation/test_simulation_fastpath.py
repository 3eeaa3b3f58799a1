"""Skipping quiescent ticks (BehaviorTree.quiet) must not change anything: the same scenario run with
and without it gives bit-identical trajectories, statuses, tree states and events."""

from __future__ import annotations

import numpy as np

from grove_tui.bt.format.xml import parse_tree_text
from grove_tui.navigation.grid import build_grid
from grove_tui.navigation.theta_star import ThetaStarPlanner
from grove_tui.scenario.model import AgentSpec, RobotSpec
from grove_tui.simulation.simulation import Simulation
from grove_tui.world import parse_world
from helpers.hall import HALL, tree_xml

BODIES = [
    ('<Sequence><GoTo target="counter" waypoints="12,3"/><Queue service_point="counter" service_time="3"/>'
     '<GoTo target="exit_door"/></Sequence>', "Surprised"),
    ('<Sequence><GoTo target="counter"/><Queue service_point="counter" service_time="3"/></Sequence>', "Scared"),
    ('<Sequence><Wait duration="2"/><Queue service_point="counter" service_time="3"/></Sequence>', "Regular"),
    ('<Wander zone="hall" duration="25"/>', "Curious"),
    ('<ReactiveSequence><Inverter><IsRobotClose threshold="1.5"/></Inverter><GoTo target="fountain"/>'
     '</ReactiveSequence>', "Regular"),
    ('<Sequence><JoinGroup/><Converse target="hall" duration="6"/><GoTo target="exit_door"/></Sequence>', "Regular"),
    ('<Sequence><JoinGroup/><Converse target="hall" duration="6"/><GoTo target="exit_door"/></Sequence>', "Regular"),
    ('<Timeout msec="8000"><GoTo target="exit_door"/></Timeout>', "Threatening"),
]


def make(fast: bool) -> Simulation:
    world, _ = parse_world(HALL, "hall.yaml")
    grid = build_grid(world)
    starts = [(15, 2), (16, 9), (12, 6), (6, 9), (4, 2), (14, 4), (13, 8), (8, 3)]
    agents = [AgentSpec(id=i + 1, group=5 if i in (5, 6) else -1, start=starts[i], goals=(), zone="hall",
                        tree=f"a{i}.xml", radius=0.3, behavior=BODIES[i][1]) for i in range(len(BODIES))]
    documents = [parse_tree_text(tree_xml(body), f"a{i}.xml") for i, (body, _) in enumerate(BODIES)]
    robot = RobotSpec(start=(18, 10), goal=(3, 2), max_vel=0.6, path=((18, 10), (10, 6), (3, 2)))
    sim = Simulation.build(agents, documents, world=world, grid=grid, planner=ThetaStarPlanner(grid),
                           walls=world.walls(), robot=robot, seed=11)
    for tree in sim.trees:
        tree.fast = fast
    return sim


def test_quiescent_ticks_change_nothing():
    fast, slow = make(True), make(False)
    quiet_seen = 0
    for _ in range(int(40.0 / fast.dt)):
        fast.step()
        slow.step()
        if fast.step_count % fast.bt_every == 1:
            quiet_seen += sum(tree.quiet is not None for tree in fast.trees)
            assert all(tree.quiet is None for tree in slow.trees)
    assert quiet_seen > 200  # the skipping really happened
    assert np.array_equal(fast.crowd.pos, slow.crowd.pos)
    assert np.array_equal(fast.crowd.yaw, slow.crowd.yaw)
    assert fast.context.status == slow.context.status
    assert [(e.t, e.agent_id, e.kind) for e in fast.events] == [(e.t, e.agent_id, e.kind) for e in slow.events]
    for agent_id in fast.ids:
        assert fast.tree_status(agent_id) == slow.tree_status(agent_id)
    kinds = {e.kind for e in fast.events}
    assert {"queue_join", "queue_served", "goal_reached"} <= kinds  # the scenario exercised the nodes
