"""SFM kernels against a direct transcription of lightsfm, plus the wall and field geometry."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from grove_tui.crowd import sfm
from grove_tui.crowd.crowd import Crowd, SFMParams


def lightsfm_step(pos, vel, v0, radius, goals, goal_radius, group, walls, params, factors, dt):
    """One step of lightsfm's computeForces + updatePosition (sfm.hpp), obstacles summed, in plain Python.

    Obstacles are the closest point of each wall segment, as the wrapper would send them.
    """
    n = len(pos)
    groups: dict[int, list[int]] = {}
    for i in range(n):
        if group[i] >= 0:
            groups.setdefault(group[i], []).append(i)
    centres = {g: np.mean([pos[j] for j in members], axis=0) for g, members in groups.items()}
    new_pos = pos.copy()
    new_vel = vel.copy()
    for i in range(n):
        w_goal, w_obs, w_soc, _ = factors[i]
        p = pos[i]
        v = vel[i]
        diff = goals[i] - p
        if np.linalg.norm(diff) > goal_radius[i]:
            e = diff / np.linalg.norm(diff)
            force = w_goal * (e * v0[i] - v) / params.tau
        else:
            e = np.zeros(2)
            force = -v / params.tau
        for w in walls:
            a, b = w[:2], w[2:]
            t = np.clip(np.dot(p - a, b - a) / np.dot(b - a, b - a), 0, 1)
            o = a + t * (b - a)
            d = np.linalg.norm(p - o) - radius[i]
            force = force + w_obs * math.exp(-d / params.obstacle_sigma) * (p - o) / np.linalg.norm(p - o)
        social = np.zeros(2)
        for j in range(n):
            if j == i:
                continue
            dvec = pos[j] - p
            ddir = dvec / np.linalg.norm(dvec)
            interaction = params.lambda_ * (v - vel[j]) + ddir
            ilen = np.linalg.norm(interaction)
            idir = interaction / ilen
            theta = math.atan2(idir[0] * ddir[1] - idir[1] * ddir[0], idir @ ddir)
            big_b = params.gamma * ilen
            fv = -math.exp(-np.linalg.norm(dvec) / big_b - (params.n_prime * big_b * theta) ** 2)
            fa = -np.sign(theta) * math.exp(-np.linalg.norm(dvec) / big_b - (params.n * big_b * theta) ** 2)
            social = social + w_soc * (fv * idir + fa * np.array([-idir[1], idir[0]]))
        force = force + social
        if group[i] >= 0 and len(groups[group[i]]) >= 2:
            members = groups[group[i]]
            size = len(members)
            com = (size * centres[group[i]] - p) / (size - 1)
            rel = com - p
            if np.linalg.norm(e) > 0:
                product = e @ rel
                angle = math.acos(np.clip(product / (np.linalg.norm(e) * np.linalg.norm(rel)), -1, 1))
                if angle > math.pi / 2:
                    force = force + params.group_gaze * (product / (e @ e)) * e
            rel = centres[group[i]] - p
            dist = np.linalg.norm(rel)
            force = force + rel * params.group_coherence * (math.tanh(dist - (size - 1) / 2) + 1) / 2
            rep = np.zeros(2)
            for j in members:
                if j != i and np.linalg.norm(p - pos[j]) < radius[i] + radius[j]:
                    rep = rep + (p - pos[j])
            force = force + params.group_repulsion * rep
        nv = v + force * dt
        if np.linalg.norm(nv) > v0[i]:
            nv = nv / np.linalg.norm(nv) * v0[i]
        new_vel[i] = nv
        new_pos[i] = p + nv * dt
    return new_pos, new_vel


def test_kernel_matches_a_direct_transcription_of_lightsfm():
    rng = np.random.default_rng(4)
    # lightsfm exactly: no theta shift, no contact term, every agent and wall within range.
    params = SFMParams.lightsfm(cutoff=50.0, wall_range=50.0, wall_clearance=0.0)
    walls = np.array([[-1.0, -1.0, 9.0, -1.0], [9.0, -1.0, 9.0, 7.0]])
    crowd = Crowd(walls, params=params)
    n = 9
    for k in range(n):
        crowd.add_agent(rng.uniform((0, 0), (8, 6)), radius=float(rng.uniform(0.25, 0.4)),
                        desired_speed=float(rng.uniform(0.6, 1.5)), group=[0, 0, 0, 1, 1, -1, -1, -1, -1][k],
                        goals=[tuple(rng.uniform((0, 0), (8, 6)))], goal_radius=0.3,
                        factors=(2.0, float(rng.uniform(2, 12)), float(rng.uniform(3, 9)), 20.0))
    crowd.vel[:] = rng.uniform(-0.8, 0.8, size=(n, 2))
    pos, vel = crowd.pos.copy(), crowd.vel.copy()
    goals = np.array([crowd.current_goal(i) for i in range(n)])
    expected_pos, expected_vel = lightsfm_step(
        pos, vel, crowd.desired_speed.copy(), crowd.radius.copy(), goals, crowd.goal_radius.copy(),
        crowd.group.copy(), walls, params, crowd.factors.copy(), crowd.dt)
    crowd.step(1)
    assert np.allclose(crowd.vel, expected_vel, rtol=0, atol=1e-9)
    assert np.allclose(crowd.pos, expected_pos, rtol=0, atol=1e-9)


def test_default_cutoffs_change_little_against_full_range():
    def run(params):
        crowd = Crowd(params=params)
        local = np.random.default_rng(8)
        for _ in range(30):
            crowd.add_agent(local.uniform((0, 0), (12, 12)), goals=[tuple(local.uniform((0, 0), (12, 12)))])
        crowd.step(1)
        return crowd.vel.copy()

    full = run(SFMParams(cutoff=100.0))
    cut = run(SFMParams())
    # One step's velocity change from what the 3 m cutoff and the exp(-8) skip leave out.
    assert np.abs(full - cut).max() < 0.02


# --------------------------------------------------------------------------- walls


def wall_setup(walls, cell=2.5):
    walls = np.asarray(walls, dtype=float)
    meta, start, items = sfm.bucket_walls(walls, cell)
    return walls, meta, start, items


def test_buckets_list_every_wall_within_a_cell_of_any_point():
    rng = np.random.default_rng(0)
    walls = rng.uniform(0, 30, size=(60, 4))
    walls, meta, start, items = wall_setup(walls)
    for p in rng.uniform(-3, 33, size=(400, 2)):
        a, b = walls[:, :2], walls[:, 2:]
        t = np.clip(np.sum((p - a) * (b - a), 1) / np.sum((b - a) ** 2, 1), 0, 1)
        dist = np.hypot(*(p - (a + t[:, None] * (b - a))).T)
        near = set(np.flatnonzero(dist <= meta[sfm.W_CELL]).tolist())
        cell = sfm._wall_cell(p[0], p[1], meta)
        listed = set(items[start[cell]:start[cell + 1]].tolist()) if cell >= 0 else set()
        assert near <= listed


def test_motion_into_a_wall_slides_along_it():
    walls, meta, start, items = wall_setup([[0.0, 0.0, 10.0, 0.0]])
    x, y, vx, vy = sfm.resolve_motion(5.0, 0.2, 5.3, -0.2, 1.0, -1.0, 0.0, walls, meta, start, items)
    assert y > 0.0
    assert x == pytest.approx(5.3, abs=1e-3)  # tangential part of the motion kept
    assert vy == pytest.approx(0.0, abs=1e-12) and vx == 1.0


def test_clearance_pushes_out_but_never_through_a_wall():
    walls, meta, start, items = wall_setup([[0.0, 0.0, 10.0, 0.0], [0.0, 0.1, 10.0, 0.1]])
    # Between two walls 0.1 m apart the clearance cannot be met; the agent stays between them.
    x, y, _, _ = sfm.resolve_motion(5.0, 0.05, 5.0, 0.06, 0.0, 0.0, 0.2, walls, meta, start, items)
    assert 0.0 < y < 0.1


@settings(max_examples=200, deadline=None)
@given(
    x0=st.floats(0.2, 9.8), y0=st.floats(0.2, 9.8),
    dx=st.floats(-3.0, 3.0), dy=st.floats(-3.0, 3.0),
    clearance=st.sampled_from([0.0, 0.1, 0.175]),
)
def test_resolve_motion_never_crosses_random_walls(x0, y0, dx, dy, clearance):
    walls = np.array([[0, 0, 10, 0], [10, 0, 10, 10], [10, 10, 0, 10], [0, 10, 0, 0],
                      [3, 3, 7, 3.5], [5, 5, 5, 9], [2, 8, 4, 6], [7, 7, 7.0001, 7]], dtype=float)
    walls, meta, start, items = wall_setup(walls)
    side_before = np.sign(orient_all(walls, x0, y0))
    if np.any(side_before == 0):
        return
    x, y, _, _ = sfm.resolve_motion(x0, y0, x0 + dx, y0 + dy, dx, dy, clearance, walls, meta, start, items)
    assert math.isfinite(x) and math.isfinite(y)
    a = np.array([x0, y0])
    b = np.array([x, y])
    for w in walls:
        c, d = w[:2], w[2:]
        o1, o2 = orient(c, d, a), orient(c, d, b)
        o3, o4 = orient(a, b, c), orient(a, b, d)
        touches = o1 * o2 <= 0 and o3 * o4 <= 0 and not np.array_equal(a, b)
        assert not touches, f"motion {a} -> {b} crosses wall {w}"


def orient(p, q, r):
    return (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0])


def orient_all(walls, x, y):
    return np.array([orient(w[:2], w[2:], (x, y)) for w in walls])


def test_corner_is_felt_once_not_once_per_edge():
    square = [[0, 0, 2, 0], [2, 0, 2, 2], [2, 2, 0, 2], [0, 2, 0, 0]]
    owners = sfm.wall_endpoint_owners(np.array(square, dtype=float))
    assert owners.sum() == 4  # four corners, each owned by exactly one edge
    params = SFMParams(wall_clearance=0.0)
    crowd = Crowd(np.array(square, dtype=float), params=params)
    i = crowd.add_agent((2.5, 2.5), radius=0.3)
    crowd.step(1)
    distance = math.hypot(0.5, 0.5)
    body = 0.3 * params.body_fraction  # walls push the body (the shoulders), not the planner's envelope
    single = 10.0 * math.exp(-(distance - body) / params.obstacle_sigma)
    assert math.hypot(*crowd.vel[i]) == pytest.approx(min(single * crowd.dt, 1.0), rel=1e-9)


# --------------------------------------------------------------------------- fields


def test_field_mode_steers_along_the_planners_sampled_direction():
    from grove_tui.navigation.velocity_field import VelocityField

    rng = np.random.default_rng(1)
    vectors = rng.normal(size=(6, 8, 2))
    vectors /= np.linalg.norm(vectors, axis=2, keepdims=True)
    field = VelocityField(origin=(1.0, 2.0), resolution=0.5, vectors=vectors.astype(np.float32), exit=(20.0, 20.0))
    crowd = Crowd(params=SFMParams(social_weight=0.0, density_radius=0.0))  # the drive alone, no crowding
    field_id = crowd.register_field(field)
    points = [(2.1, 3.3), (3.7, 4.1), (1.4, 2.2)]
    for p in points:
        i = crowd.add_agent(p, desired_speed=1.0)
        crowd.set_field(i, field_id)
        crowd.set_mode(i, sfm.MODE_FIELD)
    crowd.step(1)
    for i, p in enumerate(points):
        direction = np.array(field.sample(*p))
        direction /= np.linalg.norm(direction)
        expected = 2.0 * 1.0 * direction / 0.5 * crowd.dt  # w_g v0 e / tau, from rest
        assert np.allclose(crowd.vel[i], expected, atol=1e-6)


def test_kernel_math_matches_libm():
    rng = np.random.default_rng(3)
    for x, y in rng.normal(size=(20000, 2)):
        assert sfm._fast_atan2(y, x) == pytest.approx(math.atan2(y, x), abs=5e-11)
    for x, y in [(1.0, 0.0), (-1.0, 0.0), (-1.0, -0.0), (0.0, 1.0), (0.0, -1.0), (0.0, 0.0), (-3.0, 3.0)]:
        assert sfm._fast_atan2(y, x) == pytest.approx(math.atan2(y, x), abs=5e-11)
    for x in -rng.uniform(0.0, 60.0, size=20000):
        assert sfm._fast_exp(x) == pytest.approx(math.exp(x), rel=1e-12)
    assert sfm._fast_exp(0.0) == 1.0 and sfm._fast_exp(-800.0) == 0.0


def test_motion_along_a_walls_line_stops_at_its_end():
    walls, meta, start, items = wall_setup([[0.0, 0.0, 5.0, 0.0]])
    x, y, _, _ = sfm.resolve_motion(5.3, 0.0, 4.8, 0.0, -1.0, 0.0, 0.0, walls, meta, start, items)
    assert 5.0 < x < 5.3 and y == 0.0
    x, y, _, _ = sfm.resolve_motion(7.0, 0.0, 6.0, 0.0, -1.0, 0.0, 0.0, walls, meta, start, items)
    assert (x, y) == (6.0, 0.0)


def test_a_slide_never_leaves_a_chord_through_another_wall_tip():
    """Found by hypothesis: sliding along one wall made the step's chord clip another wall's end."""
    walls = np.array([[0, 0, 10, 0], [10, 0, 10, 10], [10, 10, 0, 10], [0, 10, 0, 0],
                      [3, 3, 7, 3.5], [5, 5, 5, 9], [2, 8, 4, 6], [7, 7, 7.0001, 7]], dtype=float)
    walls, meta, start, items = wall_setup(walls)
    x0, y0 = 3.0, 4.4375
    x, y, _, _ = sfm.resolve_motion(x0, y0, x0 + 2.0, y0 + 3.0, 2.0, 3.0, 0.1, walls, meta, start, items)
    a, b = np.array([x0, y0]), np.array([x, y])
    for w in walls:
        c, d = w[:2], w[2:]
        assert not (orient(c, d, a) * orient(c, d, b) <= 0 and orient(a, b, c) * orient(a, b, d) <= 0
                    and not np.array_equal(a, b)), f"chord {a} -> {b} crosses wall {w}"


def test_the_profiler_steps_the_crowd_exactly_like_step():
    """bench/sfm.py names the costs from Crowd.profile: it must run the same physics as step()."""
    def busy(seed: int) -> Crowd:
        rng = np.random.default_rng(seed)
        crowd = Crowd(np.array([[0.0, 0.0, 10.0, 0.0], [10.0, 0.0, 10.0, 8.0], [0.0, 8.0, 10.0, 8.0]]))
        for _ in range(80):
            crowd.add_agent(rng.uniform((0.5, 0.5), (9.5, 7.5)), goals=[(12.0, 4.0)], desired_speed=1.3)
        return crowd

    stepped, profiled = busy(1), busy(1)
    stepped.step(30)
    spent = profiled.profile(30)
    assert set(spent) == set(sfm.PROFILE_PHASES) and all(v >= 0.0 for v in spent.values())
    assert np.array_equal(stepped.pos, profiled.pos) and np.array_equal(stepped.vel, profiled.vel)
    assert profiled.time == stepped.time
