"""Physics and API of the SFM crowd: goals, crossing, counterflow, groups, walls, robot, determinism."""

from __future__ import annotations

import math
import types
import warnings

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from grove_tui.crowd.crowd import (
    MODE_FACE,
    MODE_FIELD,
    MODE_GOALS,
    MODE_STOP,
    ROBOT_AS_AGENT,
    ROBOT_FEARED,
    ROBOT_IGNORED,
    Crowd,
    CrowdError,
    SFMParams,
)


def box(x0: float, y0: float, x1: float, y1: float) -> list[list[float]]:
    return [[x0, y0, x1, y0], [x1, y0, x1, y1], [x1, y1, x0, y1], [x0, y1, x0, y0]]


def moves_cross_walls(p0: np.ndarray, p1: np.ndarray, walls: np.ndarray) -> np.ndarray:
    """(N,) bool: whether each motion p0[k] -> p1[k] touches or crosses any wall segment."""
    a = p0[:, None, :]
    b = p1[:, None, :]
    c = walls[None, :, 0:2]
    d = walls[None, :, 2:4]

    def orient(p, q, r):
        return (q[..., 0] - p[..., 0]) * (r[..., 1] - p[..., 1]) - (q[..., 1] - p[..., 1]) * (r[..., 0] - p[..., 0])

    o1 = orient(c, d, a)
    o2 = orient(c, d, b)
    o3 = orient(a, b, c)
    o4 = orient(a, b, d)
    moved = np.any(p0 != p1, axis=1)[:, None]
    hit = (o1 * o2 <= 0) & (o3 * o4 <= 0) & moved
    return hit.any(axis=1)


def speed(v: np.ndarray) -> np.ndarray:
    return np.hypot(v[..., 0], v[..., 1])


# --------------------------------------------------------------------------- single agent, goals


def test_one_agent_reaches_its_goal_at_its_desired_speed():
    crowd = Crowd(np.zeros((0, 4)))
    i = crowd.add_agent((0.0, 0.0), desired_speed=1.3, goals=[(12.0, 0.0)], goal_radius=0.3)
    crowd.step(100)  # 5 s: well past the 0.5 s relaxation
    assert speed(crowd.vel[i]) == pytest.approx(1.3, abs=1e-3)
    assert crowd.vel[i, 0] > 0 and abs(crowd.vel[i, 1]) < 1e-9
    assert crowd.yaw[i] == pytest.approx(0.0, abs=1e-9)
    for _ in range(200):
        crowd.step(1)
        if crowd.goal_reached(i):
            break
    assert crowd.goal_reached(i)
    # 11.7 m at 1.3 m/s plus the start-up: about 9.5 s
    assert 8.5 <= crowd.time <= 11.0
    crowd.step(100)
    assert speed(crowd.vel[i]) < 0.05
    assert math.hypot(crowd.pos[i, 0] - 12.0, crowd.pos[i, 1]) < 0.6


def test_goal_list_pops_and_cycles():
    crowd = Crowd()
    i = crowd.add_agent((0.0, 0.0), goals=[(3.0, 0.0), (3.0, 3.0)], goal_radius=0.3, cyclic=True)
    assert crowd.current_goal(i) == (3.0, 0.0)
    assert crowd.goals_left(i) == 2
    for _ in range(200):
        crowd.step(1)
        if crowd.current_goal(i) == (3.0, 3.0):
            break
    assert crowd.current_goal(i) == (3.0, 3.0)
    assert crowd.goals(i) == [(3.0, 3.0), (3.0, 0.0)]
    crowd.advance_goal(i)
    assert crowd.current_goal(i) == (3.0, 0.0)

    j = crowd.add_agent((10.0, 10.0), goals=[(11.0, 10.0), (12.0, 10.0)], goal_radius=0.2, cyclic=False)
    crowd.step(200)
    assert crowd.current_goal(j) == (12.0, 10.0)  # the final goal stays as the front
    assert crowd.goals_left(j) == 1
    assert crowd.goal_reached(j)
    crowd.advance_goal(j)
    assert crowd.current_goal(j) is None and crowd.goals_left(j) == 0
    assert crowd.goal_reached(j)  # nothing left to reach

    crowd.append_goal(j, (14.0, 10.0))
    assert crowd.current_goal(j) == (14.0, 10.0)
    assert not crowd.goal_reached(j)


def test_goal_reached_uses_hunavsim_tolerance():
    crowd = Crowd()
    i = crowd.add_agent((0.0, 0.0), goals=[(0.39, 0.0)], goal_radius=0.3)
    assert crowd.goal_reached(i)  # 0.39 <= 0.3 + 0.1
    crowd.set_goals(i, [(0.41, 0.0)])
    assert not crowd.goal_reached(i)


# --------------------------------------------------------------------------- pairs and crowds


def test_two_agents_crossing_never_overlap():
    crowd = Crowd()
    a = crowd.add_agent((-6.0, 0.0), goals=[(6.0, 0.0)], desired_speed=1.2)
    b = crowd.add_agent((0.0, -6.0), goals=[(0.0, 6.0)], desired_speed=1.2)
    closest = math.inf
    for _ in range(400):
        crowd.step(1)
        closest = min(closest, float(np.hypot(*(crowd.pos[a] - crowd.pos[b]))))
    assert closest >= crowd.radius[a] + crowd.radius[b] - 0.1
    assert crowd.goal_reached(a) and crowd.goal_reached(b)


def test_head_on_agents_on_one_line_sidestep_instead_of_deadlocking():
    crowd = Crowd()
    a = crowd.add_agent((-5.0, 0.0), goals=[(5.0, 0.0)])
    b = crowd.add_agent((5.0, 0.0), goals=[(-5.0, 0.0)])
    crowd.step(400)
    assert crowd.goal_reached(a) and crowd.goal_reached(b)


def test_counterflow_in_a_corridor_lanes_without_deadlock():
    length, width = 24.0, 3.6
    walls = np.array([[0, 0, length, 0], [0, width, length, width]], dtype=float)
    crowd = Crowd(walls, seed=3)
    rng = np.random.default_rng(3)
    east, west = [], []
    for k in range(12):
        y = rng.uniform(0.5, width - 0.5)
        east.append(crowd.add_agent((1.0 + 0.9 * (k // 3), y), goals=[(length + 3.0, y)],
                                    goal_radius=0.5, desired_speed=rng.uniform(1.0, 1.4)))
        y = rng.uniform(0.5, width - 0.5)
        west.append(crowd.add_agent((length - 1.0 - 0.9 * (k // 3), y), goals=[(-3.0, y)],
                                    goal_radius=0.5, desired_speed=rng.uniform(1.0, 1.4)))
    for _ in range(60):  # 60 s
        crowd.step(20)
        inside = crowd.pos[:, 0] < length
        assert np.all((crowd.pos[inside, 1] > 0.0) & (crowd.pos[inside, 1] < width))
        if all(crowd.pos[i, 0] > length for i in east) and all(crowd.pos[i, 0] < 0.0 for i in west):
            break
    stuck = [i for i in east if crowd.pos[i, 0] <= length] + [i for i in west if crowd.pos[i, 0] >= 0.0]
    assert not stuck, f"agents {stuck} are still in the corridor after {crowd.time:.0f} s"
    assert crowd.time <= 60.0


def test_a_group_walks_together():
    crowd = Crowd(seed=1)
    members = [crowd.add_agent((x, y), group=7, goals=[(30.0, 0.0)], desired_speed=1.1)
               for x, y in ((0.0, 0.0), (-1.5, 1.2), (-0.8, -1.4))]
    loner = crowd.add_agent((0.0, 6.0), goals=[(30.0, 6.0)], desired_speed=1.1)
    worst = 0.0
    for step in range(500):
        crowd.step(1)
        if step > 60:
            pts = crowd.pos[members]
            spread = max(np.hypot(*(pts[p] - pts[q])) for p in range(3) for q in range(p + 1, 3))
            worst = max(worst, float(spread))
    assert worst < 2.5
    assert crowd.pos[members, 0].min() > 15.0  # still walking, not stalled by the group forces
    assert crowd.group[loner] == -1


def test_coincident_agents_separate_and_stay_finite():
    crowd = Crowd()
    for _ in range(4):
        crowd.add_agent((1.0, 1.0), goals=[(1.0, 1.0)], goal_radius=0.1)
    crowd.add_agent((1.0, 1.0))  # no goals at all
    crowd.step(200)
    assert np.all(np.isfinite(crowd.pos)) and np.all(np.isfinite(crowd.vel)) and np.all(np.isfinite(crowd.yaw))
    pts = crowd.pos
    gaps = [np.hypot(*(pts[p] - pts[q])) for p in range(5) for q in range(p + 1, 5)]
    assert min(gaps) > 0.1


# --------------------------------------------------------------------------- walls


ROOM = np.array(
    box(0.0, 0.0, 12.0, 10.0)
    + [[6.0, 0.0, 6.0, 4.5], [6.0, 5.5, 6.0, 10.0]]  # a dividing wall with a 1 m door
    + box(2.0, 6.5, 3.0, 7.5)                         # a pillar
    + [[9.0, 2.0, 10.5, 8.0]],                        # a thin slanted partition
    dtype=float,
)


@settings(max_examples=4, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(seed=st.integers(min_value=0, max_value=2**31 - 1))
def test_dense_crowd_pushed_against_walls_never_crosses_one(seed):
    rng = np.random.default_rng(seed)
    crowd = Crowd(ROOM, seed=seed)
    targets = [(14.0, 5.0), (-3.0, 12.0), (10.0, 13.0), (2.5, 7.0), (9.75, 5.0)]
    count = 0
    while count < 100:
        x, y = rng.uniform(0.5, 5.5), rng.uniform(0.5, 9.5)
        if 1.6 < x < 3.4 and 6.1 < y < 7.9:
            continue
        crowd.add_agent((x, y), radius=rng.uniform(0.2, 0.35), desired_speed=rng.uniform(1.0, 1.8),
                        goals=[targets[count % len(targets)]], goal_radius=0.2)
        count += 1
    pillar = box(2.0, 6.5, 3.0, 7.5)
    for _ in range(1200):  # 60 s
        before = crowd.pos.copy()
        crowd.step(1)
        after = crowd.pos
        assert np.all(np.isfinite(after))
        crossed = moves_cross_walls(before, after, ROOM)
        assert not crossed.any(), f"agents {np.flatnonzero(crossed)} crossed a wall"
    assert np.all((after[:, 0] > 0) & (after[:, 0] < 12) & (after[:, 1] > 0) & (after[:, 1] < 10))
    inside_pillar = (after[:, 0] > pillar[0][0]) & (after[:, 0] < pillar[0][2]) & \
        (after[:, 1] > pillar[1][1]) & (after[:, 1] < pillar[1][3])
    assert not inside_pillar.any()
    # Everyone ends at least half a radius from every wall (the clearance the crowd keeps).
    assert min_wall_distance(after, ROOM).min() >= 0.5 * crowd.radius.min() - 1e-6


def min_wall_distance(points: np.ndarray, walls: np.ndarray) -> np.ndarray:
    a = walls[None, :, 0:2]
    b = walls[None, :, 2:4]
    p = points[:, None, :]
    ab = b - a
    t = np.clip(np.sum((p - a) * ab, axis=2) / np.sum(ab * ab, axis=2), 0.0, 1.0)
    closest = a + t[..., None] * ab
    return np.hypot(*(p - closest).transpose(2, 0, 1)).min(axis=1)


def test_agents_walk_through_a_door_not_the_wall():
    crowd = Crowd(ROOM)
    agents = [crowd.add_agent((2.0 + 0.8 * (k % 4), 2.0 + 1.5 * (k // 4)), goals=[(6.0, 5.0), (8.0, 5.0)],
                              goal_radius=0.4) for k in range(8)]
    crowd.step(1200)
    assert all(crowd.pos[i, 0] > 6.0 for i in agents)


def test_spawn_near_a_wall_is_pushed_out_with_a_warning():
    crowd = Crowd(np.array(box(0, 0, 5, 5), dtype=float))
    with pytest.warns(UserWarning, match="moved to"):
        i = crowd.add_agent((0.05, 2.0), radius=0.3)
    assert crowd.pos[i, 0] == pytest.approx(crowd.params.wall_clearance * 0.3, abs=1e-9)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        crowd.add_agent((2.5, 2.5))


def test_spawn_inside_an_obstacle_moves_to_the_grids_nearest_free_point():
    class Grid:
        def is_free(self, x, y):
            return not (1.0 < x < 3.0 and 1.0 < y < 3.0)

        def nearest_free(self, x, y, max_dist=None):
            return (3.4, y)

    crowd = Crowd(np.array(box(1, 1, 3, 3), dtype=float), grid=Grid())
    with pytest.warns(UserWarning, match="inside an obstacle"):
        i = crowd.add_agent((2.0, 2.0))
    assert tuple(crowd.pos[i]) == (3.4, 2.0)

    class Blocked(Grid):
        def nearest_free(self, x, y, max_dist=None):
            return None

    crowd = Crowd(np.array(box(1, 1, 3, 3), dtype=float), grid=Blocked())
    with pytest.raises(CrowdError, match="no free cell"):
        crowd.add_agent((2.0, 2.0))


# --------------------------------------------------------------------------- modes and knobs


def test_stop_face_speed_factors_and_active():
    crowd = Crowd()
    i = crowd.add_agent((0.0, 0.0), goals=[(20.0, 0.0)], desired_speed=1.0, yaw=0.0)
    crowd.step(40)
    crowd.set_mode(i, MODE_STOP)
    crowd.step(60)
    assert speed(crowd.vel[i]) < 0.01
    stopped_at = crowd.pos[i].copy()

    crowd.set_face_target(i, (stopped_at[0], stopped_at[1] + 5.0))
    crowd.set_mode(i, MODE_FACE)
    crowd.step(20)
    assert crowd.yaw[i] == pytest.approx(math.pi / 2, abs=1e-3)
    assert np.hypot(*(crowd.pos[i] - stopped_at)) < 0.05

    crowd.set_mode(i, MODE_GOALS)
    crowd.set_speed(i, 0.5)
    crowd.step(60)
    assert speed(crowd.vel[i]) == pytest.approx(0.5, abs=1e-3)
    crowd.restore_speed(i)
    crowd.step(60)
    assert speed(crowd.vel[i]) == pytest.approx(1.0, abs=1e-3)

    crowd.set_factors(i, social=12.0, other=1.0)
    assert tuple(crowd.factors[i]) == (2.0, 10.0, 12.0, 1.0)
    crowd.restore_factors(i)
    assert tuple(crowd.factors[i]) == (2.0, 10.0, 5.0, 20.0)

    j = crowd.add_agent((crowd.pos[i, 0] + 3.0, 0.0))
    crowd.set_active(j, False)
    frozen = crowd.pos[j].copy()
    crowd.step(100)
    assert np.array_equal(crowd.pos[j], frozen)
    assert crowd.pos[i, 0] > frozen[0] + 1.0  # walked through the inactive agent's spot unhindered

    k = crowd.add_agent((-5.0, -5.0))
    crowd.set_face_target(k, i)
    crowd.set_mode(k, MODE_FACE)
    crowd.step(40)
    to_i = crowd.pos[i] - crowd.pos[k]
    assert crowd.yaw[k] == pytest.approx(math.atan2(to_i[1], to_i[0]), abs=0.05)


def test_yaw_is_held_when_nearly_still():
    crowd = Crowd()
    i = crowd.add_agent((0.0, 0.0), yaw=1.0)
    crowd.vel[i] = (0.05, 0.0)  # below 0.07 m/s
    crowd.step(1)
    assert crowd.yaw[i] == 1.0


def test_bad_input_raises_crowd_errors():
    crowd = Crowd()
    i = crowd.add_agent((0.0, 0.0))
    with pytest.raises(CrowdError, match="out of range"):
        crowd.set_speed(5, 1.0)
    with pytest.raises(CrowdError, match="unknown mode"):
        crowd.set_mode(i, 9)
    with pytest.raises(CrowdError, match="no velocity field"):
        crowd.set_mode(i, MODE_FIELD)
    with pytest.raises(CrowdError, match="finite"):
        crowd.set_goals(i, [(math.nan, 0.0)])
    with pytest.raises(CrowdError, match=r"\(M, 4\)"):
        Crowd(np.zeros((3, 3)))
    with pytest.raises(CrowdError, match="unknown field id"):
        crowd.set_field(i, 0)
    with pytest.raises(CrowdError, match="no robot"):
        crowd.command_robot(1.0, 0.0)


# --------------------------------------------------------------------------- velocity fields


def field_towards(exit_point, width, height, resolution=0.5):
    rows, cols = int(height / resolution), int(width / resolution)
    ys = (np.arange(rows) + 0.5) * resolution
    xs = (np.arange(cols) + 0.5) * resolution
    gx, gy = np.meshgrid(xs, ys)
    vx = exit_point[0] - gx
    vy = exit_point[1] - gy
    norm = np.hypot(vx, vy)
    norm[norm == 0] = 1.0
    vectors = np.stack([vx / norm, vy / norm], axis=-1).astype(np.float32)
    return types.SimpleNamespace(origin=(0.0, 0.0), resolution=resolution, vectors=vectors, exit=exit_point)


def test_field_following_agents_reach_the_exit():
    walls = np.array(box(0, 0, 10, 8), dtype=float)
    crowd = Crowd(walls, seed=2)
    field_id = crowd.register_field(field_towards((9.5, 4.0), 10, 8))
    rng = np.random.default_rng(2)
    agents = []
    for _ in range(10):
        i = crowd.add_agent(rng.uniform((0.5, 0.5), (4.0, 7.5)), goal_radius=0.6)
        crowd.set_field(i, field_id)
        crowd.set_mode(i, MODE_FIELD)
        agents.append(i)
    reached: set[int] = set()
    for _ in range(60):
        crowd.step(10)
        for i in agents:
            if i not in reached and crowd.goal_reached(i):
                reached.add(i)
                crowd.set_active(i, False)  # evacuated
    assert reached == set(agents)


# --------------------------------------------------------------------------- robot


def test_robot_follows_its_path_then_obeys_commands():
    walls = np.array(box(-1, -1, 8, 8), dtype=float)
    crowd = Crowd(walls)
    crowd.set_robot((0.0, 0.0), radius=0.3, max_speed=0.8, path=[(0.0, 0.0), (5.0, 0.0), (5.0, 5.0)])
    top_speed = 0.0
    for _ in range(300):
        crowd.step(1)
        top_speed = max(top_speed, float(speed(crowd.robot_vel)))
        if crowd.robot_path_done:
            break
    assert crowd.robot_path_done
    assert np.allclose(crowd.robot_pos, (5.0, 5.0), atol=0.05)
    assert top_speed <= 0.8 + 1e-9
    assert 12.0 <= crowd.time <= 13.5  # 10 m at 0.8 m/s
    assert crowd.robot_yaw == pytest.approx(math.pi / 2, abs=0.05)

    crowd.command_robot(3.0, 0.0)  # clipped to max speed, straight at the wall x = 8
    crowd.step(200)
    assert speed(crowd.robot_vel) <= 0.8 + 1e-9
    assert 7.0 < crowd.robot_pos[0] < 8.0  # stopped by the wall, on its side
    crowd.clear_robot_command()
    crowd.set_robot_path([(5.0, 5.0)])
    crowd.step(200)
    assert np.allclose(crowd.robot_pos, (5.0, 5.0), atol=0.05)


def test_pedestrians_perceive_the_robot_per_behaviour():
    def closest_approach(interaction, params=None):
        crowd = Crowd(params=params)
        crowd.set_robot((0.0, 0.0), radius=0.3, max_speed=0.0)
        i = crowd.add_agent((-6.0, 0.05), goals=[(6.0, 0.05)], robot_interaction=interaction)
        best = math.inf
        for _ in range(300):
            crowd.step(1)
            best = min(best, float(np.hypot(*(crowd.pos[i] - crowd.robot_pos))))
        return best, crowd.goal_reached(i)

    as_agent, reached = closest_approach(ROBOT_AS_AGENT)
    assert as_agent > 0.5 and reached
    ignored, reached = closest_approach(ROBOT_IGNORED)
    # no social force from it (HuNavSim's reacting agents), but bodies touch: pressed against it, not
    # through it (the radii add up to 0.55 m), and round it to the goal
    assert 0.3 < ignored < as_agent and reached
    hunav, reached = closest_approach(ROBOT_IGNORED, SFMParams.named("lightsfm"))
    assert hunav < 0.1 and reached  # HuNavSim's forces exactly: straight through it
    feared, _ = closest_approach(ROBOT_FEARED)
    assert feared > as_agent


# --------------------------------------------------------------------------- determinism


def build_busy_crowd(seed: int, threshold: int) -> Crowd:
    crowd = Crowd(ROOM, seed=seed)
    crowd.parallel_threshold = threshold
    for k in range(60):
        x, y = crowd.rng.uniform(0.5, 5.5), crowd.rng.uniform(0.5, 6.0)
        crowd.add_agent((x, y), group=k % 7 if k < 14 else -1, goals=[(8.0, 5.0), (2.0, 2.0)], cyclic=True,
                        desired_speed=float(crowd.rng.uniform(0.8, 1.5)))
    crowd.set_robot((8.0, 8.0), path=[(8.0, 8.0), (3.0, 8.0)])
    return crowd


def test_same_seed_gives_identical_arrays():
    a = build_busy_crowd(11, threshold=10**9)
    b = build_busy_crowd(11, threshold=10**9)
    a.step(300)
    for _ in range(3):
        b.step(100)
    for name in ("pos", "vel", "yaw"):
        assert np.array_equal(getattr(a, name), getattr(b, name))
    assert np.array_equal(a.robot_pos, b.robot_pos)
    c = build_busy_crowd(12, threshold=10**9)
    c.step(300)
    assert not np.array_equal(a.pos, c.pos)


def test_parallel_and_serial_kernels_agree_exactly():
    serial = build_busy_crowd(5, threshold=10**9)
    parallel = build_busy_crowd(5, threshold=0)
    serial.step(200)
    parallel.step(200)
    assert np.array_equal(serial.pos, parallel.pos)
    assert np.array_equal(serial.vel, parallel.vel)
    assert np.array_equal(serial.yaw, parallel.yaw)


def test_many_agents_grow_storage_and_goal_lists():
    crowd = Crowd(params=SFMParams(social_weight=5.0))
    for k in range(40):
        crowd.add_agent((k * 1.0, 0.0), goals=[(k * 1.0, float(g)) for g in range(1, 1 + k % 9)])
    assert crowd.n == 40
    assert crowd.goals(39) == [(39.0, float(g)) for g in range(1, 4)]
    crowd.step(5)
    assert np.all(np.isfinite(crowd.pos))


def test_non_finite_state_written_from_outside_is_refused():
    crowd = Crowd()
    i = crowd.add_agent((0.0, 0.0))
    crowd.pos[i] = (math.nan, 0.0)
    with pytest.raises(CrowdError, match=r"agents \[0\] have a non-finite"):
        crowd.step(1)
