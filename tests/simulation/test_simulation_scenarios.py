"""Scenario tests: behavior trees driving the real numba crowd in a small world.

World: a 20 m x 12 m hall, a service counter on the west wall (people stand at (2.2, 6)), a fountain
in the north middle, and an exit door (2 m) in the middle of the east wall.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from helpers.hall import HALL, agent, run_until, running, simulate, tree_xml  # noqa: F401

from grove_tui.scenario.model import RobotSpec, Scenario
from grove_tui.simulation.simulation import REACTION_DEFAULTS, Simulation
from grove_tui.world import parse_world  # noqa: F401

# ---- queue -------------------------------------------------------------------------------------

def test_queue_of_eight_forms_in_order_with_the_spacing_and_advances(hall):
    starts = [(9 + 2.5 * (i % 4), 2.5 + 5.5 * (i // 4)) for i in range(8)]
    agents = [agent(i + 1, starts[i], radius=0.25) for i in range(8)] + [agent(9, (17, 10), radius=0.25)]
    body = '<Queue service_point="counter" spacing="0.6" service_time="60"/>'
    late = f'<Delay delay_msec="25000">{body}</Delay>'  # arrives after the line has formed
    sim = simulate(hall, agents, [body] * 8 + [late])
    queue_of = sim.context.queues

    def formed():
        q = queue_of.queues.get("counter")
        return q is not None and len(q.members) == 9 and all(
            math.dist(sim.crowd.pos[r], q.slot_point(k)) < 0.2 for k, r in enumerate(q.members))

    assert run_until(sim, formed, 50.0), "the queue did not form within 50 s"
    q = queue_of.queues["counter"]
    assert q.spacing == pytest.approx(0.6)
    assert q.slot_point(0) == pytest.approx((2.2, 6.0))
    direction = np.array(q.direction)
    assert direction @ np.array([1.0, 0.0]) > 0.95  # away from the counter, into the hall
    positions = np.array([sim.crowd.pos[r] for r in q.members])
    along = (positions - np.array(q.service_point)) @ direction
    assert np.all(np.diff(along) > 0.4)  # in order along the line
    assert np.allclose(np.diff(along), 0.6, atol=0.2)  # at the set spacing
    assert q.members[-1] == sim.context.row_of[9]  # the late arrival joined at the back
    assert sim.frame().counters.in_queue == 9
    served_first = q.members[0]
    order_before = list(q.members)

    assert run_until(sim, lambda: sim.frame().counters.served == 1, 120.0)
    assert served_first not in q.members and q.members == order_before[1:]
    assert q.head_since is None or sim.time - q.head_since < 1.0  # the next head started being served at once

    assert run_until(sim, lambda: all(math.dist(sim.crowd.pos[r], q.slot_point(k)) < 0.25
                                      for k, r in enumerate(q.members)), sim.time + 15.0)
    positions = np.array([sim.crowd.pos[r] for r in q.members])
    along = (positions - np.array(q.service_point)) @ direction
    assert along[0] == pytest.approx(0.0, abs=0.25)  # everyone moved up one slot
    assert np.allclose(np.diff(along), 0.6, atol=0.2)
    kinds = [e.kind for e in sim.events]
    assert kinds.count("queue_join") == 9 and kinds.count("queue_served") == 1
    assert sim.tree_result[served_first] == "done"


def test_served_people_step_aside_to_spots_of_their_own(hall):
    """Served people used to step to one spot beside the counter and jostle there for the rest of the run."""
    starts = [(9 + 2.5 * (i % 3), 2.5 + 5.5 * (i // 3)) for i in range(6)]
    agents = [agent(i + 1, starts[i], radius=0.25) for i in range(6)]
    body = '<Queue service_point="counter" spacing="0.6" service_time="2"/>'
    sim = simulate(hall, agents, [body] * 6)
    assert run_until(sim, lambda: sim.frame().counters.served == 6, 120.0)
    sim.run(10.0)
    spots = np.array(sim.context.queues.queues["counter"].aside)
    assert len(spots) == 6
    gaps = np.hypot(*(spots[:, None] - spots[None]).transpose(2, 0, 1))[np.triu_indices(6, 1)]
    assert gaps.min() >= 0.8 - 1e-9
    pos = sim.crowd.pos[:6]
    assert np.all(np.hypot(*(pos[:, None] - spots[None]).transpose(2, 0, 1)).min(axis=1) < 0.4)  # they got there
    apart = np.hypot(*(pos[:, None] - pos[None]).transpose(2, 0, 1))[np.triu_indices(6, 1)]
    assert apart.min() > 0.6  # nobody stands in anybody's way
    line = np.array([2.2, 6.0])
    assert np.all(np.abs(spots[:, 1] - line[1]) >= 1.2 - 1e-9)  # beside the line, not in it


def test_a_contact_counts_once_until_the_two_move_apart(hall):
    sim = simulate(hall, [agent(1, (5, 6)), agent(2, (7, 6))], ['<Wait duration="100"/>'] * 2)

    touching = 0.7 * sim.crowd.params.body_fraction  # two bodies of radius 0.35 touch at the shoulders

    def place(gap: float) -> int:
        sim.crowd.pos[0] = (5.0, 6.0)
        sim.crowd.pos[1] = (5.0 + touching + gap, 6.0)
        sim.tick_trees()
        return sim.frame().counters.collisions

    assert place(0.5) == 0
    assert place(-0.05) == 1  # bodies overlap: one collision
    assert place(0.03) == 1  # brushing apart and back in a dense spot is the same contact
    assert place(-0.02) == 1
    assert place(0.3) == 1  # now they are apart
    assert place(-0.05) == 2  # and this is a new contact


# ---- conversation --------------------------------------------------------------------------------

def test_conversation_of_four_forms_a_circle_facing_the_centre(hall):
    starts = [(4, 2), (15, 3), (16, 10), (5, 10)]
    agents = [agent(i + 1, starts[i], group=1) for i in range(4)]
    body = '<Converse target="hall" duration="10"/>'  # the hall's anchor point is (10, 6)
    sim = simulate(hall, agents, [body] * 4)
    centre = np.array(sim.context.resolve_target("hall"))
    assert run_until(sim, lambda: all(s == "talking" for s in sim.frame().status), 40.0)
    started = sim.time
    sim.run(3.0)  # let the last arrival finish turning
    pos = sim.crowd.pos[:4]
    radius = 0.5 + 0.2 * 3
    assert np.allclose(np.hypot(*(pos - centre).T), radius, atol=0.2)
    angles = np.sort(np.arctan2(pos[:, 1] - centre[1], pos[:, 0] - centre[0]))
    gaps = np.diff(np.concatenate([angles, angles[:1] + 2 * np.pi]))
    assert gaps.min() > np.radians(60)  # spread around the circle
    bearing = np.arctan2(centre[1] - pos[:, 1], centre[0] - pos[:, 0])
    facing_error = np.abs(np.angle(np.exp(1j * (sim.crowd.yaw[:4] - bearing))))
    assert facing_error.max() < 0.15
    assert run_until(sim, lambda: all(sim.finished), started + 12.0)
    assert sim.time - started == pytest.approx(10.0, abs=0.3)
    assert all(result == "done" for result in sim.tree_result)

def test_friends_walking_together_to_a_circle_each_take_their_own_spot(hall):
    # Three friends arrive as one walking group (group forces hold them together), along waypoints
    # planned to the circle, at spots on every side of it: the circle must start, not stall with
    # everyone jostling for the last waypoint and pulling each other back from their spots.
    for waypoint in ("8.0,7.0", "10,4.2"):
        for starts in ([(3, 2.0), (3.6, 2.5), (3, 3.0)], [(17, 10.0), (16.4, 10.5), (17, 9.5)],
                       [(10, 1.5), (10.6, 1.8), (9.4, 1.8)]):
            agents = [agent(i + 1, starts[i], group=2) for i in range(3)]
            body = f'<Converse target="hall" waypoints="{waypoint}" duration="10"/>'  # centre (10, 6)
            sim = simulate(hall, agents, [body] * 3)
            assert run_until(sim, lambda: all(s == "talking" for s in sim.frame().status), 40.0), (waypoint, starts)

# ---- group -------------------------------------------------------------------------------------

def test_group_walks_together_to_the_door(hall):
    starts = [(3, 2.0), (3.8, 2.6), (3, 3.2), (3.8, 1.6)]
    speeds = [1.4, 0.8, 1.2, 1.0]
    agents = [agent(i + 1, starts[i], group=3, max_vel=speeds[i]) for i in range(4)]
    body = '<Sequence><JoinGroup/><GoTo target="exit_door" tolerance="0.8"/></Sequence>'
    sim = simulate(hall, agents, [body] * 4)
    spread = 0.0
    arrival: dict[int, float] = {}
    while sim.time < 40.0 and len(arrival) < 4:
        sim.step()
        pos = sim.crowd.pos[:4]
        spread = max(spread, float(np.max(np.hypot(*(pos[:, None] - pos[None]).transpose(2, 0, 1)))))
        for event in sim.events:
            if event.kind == "goal_reached":
                arrival.setdefault(event.agent_id, event.t)
    assert len(arrival) == 4, "not everyone reached the door"
    assert set(sim.crowd.group[:4].tolist()) == {100001}  # one SFM group
    assert np.allclose(sim.crowd.desired_speed[:4], 0.8)  # at the slowest member's pace
    assert spread < 3.5  # they stayed together all the way
    assert max(arrival.values()) - min(arrival.values()) < 4.0
    door = np.array([20.0, 6.0])
    assert np.all(np.hypot(*(sim.crowd.pos[:4] - door).T) < 1.6)


def test_a_walker_stuck_behind_an_obstacle_walks_round_it(hall):
    # A stale route straight through the fountain (as after being pushed off the planned line): the
    # social forces hold the walker against it for ever unless it replans from where it stands.
    sim = simulate(hall, [agent(1, (10, 7.5))], ['<GoTo target="hall" x="10" y="11.5" waypoints="10,11.5" tolerance="0.3"/>'])
    assert run_until(sim, lambda: sim.tree_result[0] == "done", 40.0), sim.crowd.pos[0]


def test_a_walking_group_with_a_member_stuck_behind_an_obstacle_arrives(hall):
    bodies = [f'<Sequence><JoinGroup/><GoTo target="hall" x="{x}" y="11" waypoints="{wp}" tolerance="0.3"/></Sequence>'
              for x, wp in ((17.5, "10,11.5"), (18, "18,11"), (18.5, "18.5,11"))]
    group = [agent(1, (10, 7.5), group=4), agent(2, (8.2, 11.3), group=4), agent(3, (7.4, 11.3), group=4)]
    sim = simulate(hall, group, bodies)
    assert run_until(sim, lambda: all(r == "done" for r in sim.tree_result), 60.0), sim.crowd.pos[:3]


# ---- reactions to the robot --------------------------------------------------------------------

@pytest.mark.parametrize("behavior", ["Surprised", "Scared", "Curious", "Threatening"])
def test_reactions_trigger_at_their_distance_and_end_after_their_duration(hall, behavior):
    node, distance, duration, once = REACTION_DEFAULTS[behavior]
    robot = RobotSpec(start=(19.0, 7.0), goal=(1.0, 7.0), max_vel=0.5, path=((19.0, 7.0), (3.0, 7.0)))
    agents = [agent(1, (6.0, 6.0), behavior=behavior)]
    sim = simulate(hall, agents, ['<Wait duration="500"/>'], robot=robot)

    assert run_until(sim, lambda: running(sim, 1, node), 60.0), f"{node} never started"
    started = sim.time
    gap = float(np.hypot(*(sim.crowd.pos[0] - sim.crowd.robot_pos)))
    # triggered within one BT period (0.1 s at 0.5 m/s -> 0.05 m) of crossing the distance
    assert distance - 0.15 <= gap <= distance + 1e-6
    start_pos = sim.crowd.pos[0].copy()
    samples = []
    while running(sim, 1, node) and sim.time < started + duration + 5:
        sim.step()
        samples.append((sim.time, float(np.hypot(*(sim.crowd.pos[0] - sim.crowd.robot_pos))),
                        sim.crowd.pos[0].copy()))
    ended = sim.time
    assert ended - started == pytest.approx(duration, abs=0.2)
    assert running(sim, 1, "Wait")  # back to the routine
    moved = float(np.hypot(*(samples[-1][2] - start_pos)))
    if behavior == "Surprised":
        assert moved < 0.3  # stops and turns to the robot
    elif behavior == "Scared":
        assert max(d for _, d, _ in samples[:60]) > gap + 0.5  # hurries away
    elif behavior == "Curious":
        assert min(d for _, d, _ in samples) < gap - 1.0  # goes to look at it
    elif behavior == "Threatening":
        assert min(d for _, d, _ in samples) < 2.0  # steps in front of it
    if once:  # no second reaction while the robot is still around
        assert not run_until(sim, lambda: running(sim, 1, node), sim.time + 5.0)


def test_impassive_agents_see_the_robot_as_an_obstacle(hall):
    from grove_tui.crowd.crowd import ROBOT_AS_OBSTACLE

    sim = simulate(hall, [agent(1, (6, 6), behavior="Impassive")], ['<Wait duration="5"/>'])
    assert sim.crowd.robot_interaction[0] == ROBOT_AS_OBSTACLE


# ---- evacuation -------------------------------------------------------------------------------

def test_follow_velocity_field_agents_leave_through_the_exit(hall):
    from grove_tui.navigation.velocity_field import build_velocity_field

    world, grid, planner = hall
    exit_point = world.roi("exit_door").point
    starts = [(2.5 + 1.5 * (i % 3), 2.0 + 3.5 * (i // 3)) for i in range(9)]
    centroid = np.mean(starts, axis=0)
    field = build_velocity_field(grid, planner.plan(centroid, exit_point), exit_point, planner=planner)
    agents = [agent(i + 1, starts[i], group=0) for i in range(9)]
    body = '<FollowVelocityField exit="exit_door" field="group_0"/>'
    sim = simulate(hall, agents, [body] * 9, fields={"group_0": field})
    inside = True
    while sim.time < 60.0 and sim.frame().counters.evacuated < 9:
        sim.step()
        active = sim.crowd.active[:9]
        pos = sim.crowd.pos[:9][active]
        in_hall = np.all((pos > -0.01) & (pos < np.array([20.01, 12.01])), axis=1)
        # past the east wall only through the 2 m door (5..7), by at most a tick's walk
        in_doorway = (pos[:, 0] < 20.3) & (pos[:, 1] > 5.0) & (pos[:, 1] < 7.0)
        inside &= bool(np.all(in_hall | in_doorway))
    assert sim.frame().counters.evacuated == 9
    assert not sim.crowd.active[:9].any()
    assert inside  # nobody left the hall through a wall on the way
    assert len(sim.frame().ids) == 0
    assert [e.kind for e in sim.events].count("evacuated") == 9
    # each left through the opening: past the door line, within the door's span
    assert np.all(sim.crowd.pos[:9, 0] > 20.0)
    assert np.all(np.abs(sim.crowd.pos[:9, 1] - 6.0) < 1.0)


def test_an_agent_told_to_leave_twice_is_evacuated_once(hall):
    """A small model's tree may repeat FollowVelocityField; the counter showed 3 evacuations per person."""
    from grove_tui.navigation.velocity_field import build_velocity_field

    world, grid, planner = hall
    exit_point = world.roi("exit_door").point
    starts = [(14.0, 4.0), (14.0, 6.0), (14.0, 8.0)]
    field = build_velocity_field(grid, planner.plan(starts[1], exit_point), exit_point, planner=planner)
    leave = '<FollowVelocityField exit="exit_door" field="group_0"/>'
    sim = simulate(hall, [agent(i + 1, p, group=0) for i, p in enumerate(starts)], [f"<Sequence>{leave * 3}</Sequence>"] * 3,
                   fields={"group_0": field})
    assert run_until(sim, lambda: all(sim.finished), 40.0)
    assert sim.frame().counters.evacuated == 3
    assert [e.kind for e in sim.events].count("evacuated") == 3
    assert sim.tree_result == ["done"] * 3


# ---- navigation ---------------------------------------------------------------------------------

def test_goto_walks_the_injected_waypoints_then_the_target(hall):
    sim = simulate(hall, [agent(1, (17, 10))], ['<GoTo target="counter" x="2.2" y="6" waypoints="15,2;5,2"/>'])
    sim.step()
    assert sim.crowd.goals(0) == [(15.0, 2.0), (5.0, 2.0), (2.2, 6.0)]
    closest = [np.inf, np.inf]
    assert run_until(sim, lambda: sim.finished[0], 40.0)
    # re-run to record the path: passes close to both waypoints
    sim = simulate(hall, [agent(1, (17, 10))], ['<GoTo target="counter" x="2.2" y="6" waypoints="15,2;5,2"/>'])
    while not sim.finished[0] and sim.time < 40.0:
        sim.step()
        for k, wp in enumerate(((15, 2), (5, 2))):
            closest[k] = min(closest[k], math.dist(sim.crowd.pos[0], wp))
    assert max(closest) < 0.5
    assert math.dist(sim.crowd.pos[0], (2.2, 6.0)) <= 0.4
    assert sim.frame().counters.reached_goals == 1


def test_goto_without_waypoints_plans_around_the_fountain(hall):
    sim = simulate(hall, [agent(1, (10, 7.5))], ['<GoTo target="top" x="10" y="11.6"/>'])
    sim.step()
    assert len(sim.crowd.goals(0)) > 1  # straight up would go through the fountain
    assert run_until(sim, lambda: sim.finished[0], 40.0)


def test_wander_roams_inside_the_zone_for_its_duration(hall):
    sim = simulate(hall, [agent(1, (6, 6))], ['<Wander zone="hall" duration="20"/>'])
    seen = []
    while not sim.finished[0] and sim.time < 30.0:
        sim.step()
        seen.append(sim.crowd.pos[0].copy())
    assert sim.finished[0] and sim.time == pytest.approx(20.0, abs=0.2)
    seen = np.array(seen)
    assert np.ptp(seen[:, 0]) + np.ptp(seen[:, 1]) > 3.0  # it went places
    assert sim.context.counters.reached_goals >= 1


def test_wait_then_say_something_shows_in_the_status(hall):
    sim = simulate(hall, [agent(1, (6, 6))], ['<Sequence><Wait duration="2"/><SaySomething message="hello"/></Sequence>'])
    sim.run(1.0)
    assert sim.frame().status[0] == "waiting"
    sim.run(1.5)
    assert sim.frame().status[0].startswith('says "hello"')


# ---- the bundle entry point ---------------------------------------------------------------------

def test_from_scenario_loads_world_trees_and_runs(tmp_path, hall):
    (tmp_path / "hall.yaml").write_text(HALL)
    (tmp_path / "trees").mkdir()
    bodies = {1: '<GoTo target="counter"/>', 2: '<Queue service_point="counter" service_time="2"/>'}
    for i, body in bodies.items():
        (tmp_path / "trees" / f"agent_{i}.xml").write_text(tree_xml(body))
    scenario = Scenario(world=str(tmp_path / "hall.yaml"), preset="queuing", prompt="test", seed=3, models={},
                        agents=(agent(1, (12, 3)), agent(2, (14, 9))),
                        robot=RobotSpec(start=(18, 2), goal=(18, 10)))
    frames = []
    sim = Simulation.from_scenario(scenario, tmp_path)
    final = sim.run(30.0, on_frame=frames.append)
    assert len(frames) == 300  # one per BT period (10 Hz)
    assert final.t == pytest.approx(30.0)
    assert list(final.ids) == [1, 2]
    assert final.robot is not None and final.robot[1] > 9.0  # the scripted robot walked to its goal
    assert final.counters.reached_goals == 1 and final.counters.served == 1
    assert final.counters.closest_robot_approach < 20
    with pytest.raises(ValueError):
        final.pos[0, 0] = 1.0  # frames are immutable snapshots
    assert sim.tree_status(2)[0][1:] == ("Queue", "SUCCESS")


def test_hunavsim_regular_tree_walks_its_goals_forever(hall):
    body = ('<Fallback><Sequence><Inverter><IsGoalReached/></Inverter><RegularNav/></Sequence><UpdateGoal/>'
            '</Fallback>')
    sim = simulate(hall, [agent(1, (5, 6), goals=((5.0, 6.0), (15.0, 6.0)))], [body])
    xs = []
    while sim.time < 45.0:
        sim.step()
        xs.append(float(sim.crowd.pos[0, 0]))
    xs = np.array(xs)
    assert not sim.finished[0]  # HuNavSim-style trees are ticked for the whole run
    crossings = np.count_nonzero(np.diff(np.sign(xs - 10.0)) != 0)
    assert crossings >= 3  # back and forth between the two goals
    assert xs.max() > 14.0 and xs[len(xs) // 2:].min() < 6.0  # reached the far goal, then came back
