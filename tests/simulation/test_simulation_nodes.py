"""Every leaf of the manifest runs on the real crowd, and the HuNavSim agent/robot interactions do
what their names say."""

from __future__ import annotations

import math

import numpy as np
import pytest

from grove_tui.bt.format.manifest import NODES
from grove_tui.crowd.leaves.registry import LEAF_CLASSES
from grove_tui.scenario.model import RobotSpec
from helpers.hall import agent, running, simulate

# literal ports for nodes that need more than their defaults in this small world
PORTS = {
    "GoTo": 'target="counter"',
    "Queue": 'service_point="counter" service_time="1"',
    "FollowVelocityField": 'exit="exit_door"',
    "Wander": 'zone="hall" duration="3"',
    "Converse": 'target="hall" duration="2"',
    "SetBlackboard": 'value="3" output_key="k"',
    "SetGroupId": 'group_id="4"',
    "SetGoal": 'goal_id="1"',
    "LookAtPoint": 'goal_id="1"',
    "IsAtPosition": 'goal_id="1"',
    "FindNearestAgent": 'target_agent_id="{nearest}"',
    "IsAnyoneSpeaking": 'speaker_id="{speaker}" duration="1"',
    "IsAnyoneLookingAtMe": 'observer_id="{observer}" duration="1"',
    "IsSpeaking": 'duration="1"',
    "IsLookingAtMe": 'duration="1"',
    "ConversationFormation": 'goal_id="1" non_main_agent_ids="2" conversation_duration="2"',
    "SetGroupWalk": 'non_main_agent_ids="2" duration="2"',
}
ROBOT = RobotSpec(start=(12.0, 6.0), goal=(12.0, 6.5), max_vel=0.2, path=((12.0, 6.0), (12.0, 6.5)))


@pytest.mark.parametrize("name", sorted(LEAF_CLASSES))
def test_every_leaf_runs(hall, name):
    # goal 1 of the HuNavSim global goal table comes from agent 2's GoTo (goal_id + x/y, as post-processing writes)
    bodies = [f"<{name} {PORTS.get(name, '')}/>",
              '<GoTo target="fountain" x="10" y="8" goal_id="1"/>']
    sim = simulate(hall, [agent(1, (8, 6)), agent(2, (9, 5))], bodies, robot=ROBOT)
    statuses = set()
    for _ in range(100):
        sim.step()
        statuses.add(sim.tree_status(1)[0][2])
    assert statuses <= {"IDLE", "RUNNING", "SUCCESS", "FAILURE", "SKIPPED"}
    assert NODES[name].category in ("action", "condition")


def distance_to_robot(sim, row=0):
    return float(np.hypot(*(sim.crowd.pos[row] - sim.crowd.robot_pos)))


def test_approach_robot_stops_at_its_closest_distance(hall):
    robot = RobotSpec(start=(15.0, 6.0), goal=(15.0, 6.0))
    sim = simulate(hall, [agent(1, (5, 6))], ['<ApproachRobot closest_dist="1.5" max_vel="1.2" duration="25"/>'],
                   robot=robot)
    sim.run(20.0)
    assert distance_to_robot(sim) == pytest.approx(1.5, abs=0.3)
    assert running(sim, 1, "ApproachRobot")


def test_avoid_robot_keeps_its_safe_distance(hall):
    robot = RobotSpec(start=(8.0, 6.0), goal=(8.0, 6.0))
    sim = simulate(hall, [agent(1, (9, 6))], ['<AvoidRobot safe_distance="4" runaway_vel="1.5" duration="15"/>'],
                   robot=robot)
    sim.run(12.0)
    assert distance_to_robot(sim) >= 3.8


def test_block_robot_stands_in_front_of_it(hall):
    robot = RobotSpec(start=(15.0, 6.0), goal=(15.0, 6.0))
    sim = simulate(hall, [agent(1, (5, 3))], ['<BlockRobot front_dist="1.2" duration="30"/>'], robot=robot)
    sim.crowd.set_robot((15.0, 6.0), yaw=math.pi)  # facing west, toward the agent's side
    sim.run(20.0)
    assert np.allclose(sim.crowd.pos[0], (13.8, 6.0), atol=0.35)


def test_follow_agent_walks_behind_the_other(hall):
    bodies = ['<FollowAgent closest_dist="1.5" max_vel="1.5" duration="30"/>', '<GoTo target="exit_door"/>']
    # no SFM group: group coherence would hold the leader back to the slowed follower
    sim = simulate(hall, [agent(1, (3, 9)), agent(2, (4, 6))], bodies)
    gaps = []
    while not sim.finished[1] and sim.time < 30:
        sim.step()
        gaps.append(float(np.hypot(*(sim.crowd.pos[0] - sim.crowd.pos[1]))))
    assert sim.finished[1]
    assert max(gaps[-40:]) < 2.5  # kept up with the leader to the door
    assert sim.crowd.pos[0, 0] > 15


def test_look_at_robot_turns_and_succeeds(hall):
    robot = RobotSpec(start=(5.0, 10.0), goal=(5.0, 10.0))
    sim = simulate(hall, [agent(1, (5, 4))], ['<LookAtRobot/>'], robot=robot)
    sim.run(3.0)
    assert sim.tree_result[0] == "done"
    assert sim.crowd.yaw[0] == pytest.approx(math.pi / 2, abs=0.05)


def test_say_something_is_heard_by_a_listener_within_range(hall):
    bodies = ['<Sequence><IsAnyoneSpeaking distance_threshold="5" duration="5" speaker_id="{who}"/>'
              '<SaySomething message="heard you"/></Sequence>',
              '<Sequence><Wait duration="1"/><SaySomething message="hello"/></Sequence>',
              '<Sequence><IsAnyoneSpeaking distance_threshold="3" duration="3" speaker_id="{who}"/>'
              '<SaySomething message="far away"/></Sequence>']
    sim = simulate(hall, [agent(1, (5, 6)), agent(2, (7, 6)), agent(3, (15, 6))], bodies)
    sim.run(4.0)
    assert sim.tree_result == ["done", "done", "failed"]
    assert sim.trees[0].blackboard.get("who") == 2
    assert sim.frame().status[0].startswith('says "heard you"')


def test_hunavsim_conversation_formation_drives_every_participant(hall):
    bodies = ['<ConversationFormation goal_id="1" non_main_agent_ids="2,3" conversation_duration="4"/>',
              '<AlwaysSuccess/>', '<AlwaysSuccess/>',  # the others' own trees leave their intents alone
              '<Sequence><GoTo target="centre" x="10" y="6" goal_id="1"/><Wait duration="60"/></Sequence>']
    sim = simulate(hall, [agent(1, (4, 3)), agent(2, (15, 3)), agent(3, (15, 10)), agent(4, (10, 2))], bodies)
    assert run_until_talking(sim)
    pos = sim.crowd.pos[:3]
    assert np.allclose(np.hypot(pos[:, 0] - 10, pos[:, 1] - 6), 0.5 + 0.2 * 2, atol=0.25)
    sim.run(6.0)
    assert sim.tree_result[0] == "done"


def run_until_talking(sim) -> bool:
    while sim.time < 30:
        sim.step()
        if all(s == "talking" for s in sim.frame().status[:3]):
            return True
    return False
