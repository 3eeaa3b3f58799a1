"""Metrics on hand-built trajectories whose answers are known exactly."""

from __future__ import annotations

import math

import numpy as np
import pytest

from grove_tui.analysis.force_metrics import force_series
from grove_tui.analysis.metrics import (
    MetricsError,
    SimEvent,
    Trajectories,
    compute_metrics,
    crowd_metrics,
    group_space_intrusions,
    queue_metrics,
    robot_metrics,
    wall_penetrations,
)

DT = 0.1


def rows_for(tracks: dict[int, list[tuple[float, float]]], group: dict[int, int] | None = None) -> np.ndarray:
    """Build recorder rows as the simulator records them: velocity of the step that led to the frame,
    yaw held while standing still."""
    rows = []
    for agent_id, pts in tracks.items():
        pts_arr = np.asarray(pts, dtype=float)
        vel = np.vstack([np.zeros((1, 2)), np.diff(pts_arr, axis=0) / DT])
        yaw = 0.0
        for f, ((x, y), (vx, vy)) in enumerate(zip(pts_arr, vel, strict=True)):
            if vx or vy:
                yaw = math.atan2(vy, vx)
            rows.append([f, f * DT, agent_id, x, y, vx, vy, yaw, (group or {}).get(agent_id, -1)])
    return np.asarray(rows, dtype=float)


def test_robot_passing_a_standing_person_counts_intrusions_by_band():
    # Robot walks along y=0 from x=0 to x=9 in 10 frames; a person stands at (5, 1.0).
    robot = [(float(x), 0.0) for x in range(10)]
    person = [(5.0, 1.0)] * 10
    traj = Trajectories.from_rows(rows_for({0: robot, 1: person}))
    m = robot_metrics(traj, robot_radius=0.3, person_radius=0.35, goal=(9.0, 0.0), goal_radius=0.3)
    gaps = [max(0.0, math.hypot(x - 5.0, 1.0) - 0.65) for x in range(10)]
    assert m["minimum_distance_to_people"] == pytest.approx(min(gaps))
    assert m["intimate_space_intrusions"] == pytest.approx(100 * sum(g < 0.45 for g in gaps) / 10)
    assert m["personal_space_intrusions"] == pytest.approx(100 * sum(0.45 <= g < 1.2 for g in gaps) / 10)
    assert m["social_space_intrusions"] == pytest.approx(100 * sum(1.2 <= g < 3.6 for g in gaps) / 10)
    assert m["path_length"] == pytest.approx(9.0)
    assert m["completed"] == 1.0
    assert m["time_to_reach_goal"] == pytest.approx(0.9)
    assert m["robot_on_person_collision"] == 0.0 and m["person_on_robot_collision"] == 0.0


def test_robot_driving_into_a_person_is_one_robot_on_person_collision():
    person = [(2.0, 0.0)] * 5
    robot = [(0.0, 0.0), (0.5, 0.0), (1.0, 0.0), (1.36, 0.0), (1.36, 0.0)]  # gap 2.0-1.36-0.65 < 0 -> 0
    traj = Trajectories.from_rows(rows_for({0: robot, 1: person}))
    m = robot_metrics(traj, robot_radius=0.3, person_radius=0.35)
    assert m["robot_on_person_collision"] == 1.0
    assert m["person_on_robot_collision"] == 0.0
    assert m["minimum_distance_to_people"] == 0.0


def test_person_walking_into_a_standing_robot_is_blamed_on_the_person():
    robot = [(0.0, 0.0)] * 5
    person = [(3.0, 0.0), (2.0, 0.0), (1.2, 0.0), (0.64, 0.0), (0.64, 0.0)]
    traj = Trajectories.from_rows(rows_for({0: robot, 1: person}))
    m = robot_metrics(traj, robot_radius=0.3, person_radius=0.35)
    assert m["person_on_robot_collision"] == 1.0
    assert m["robot_on_person_collision"] == 0.0


def test_heading_changes_and_time_not_moving():
    robot = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (1.0, 1.0), (1.0, 1.0)]
    traj = Trajectories.from_rows(rows_for({0: robot}))
    m = robot_metrics(traj)
    # yaw goes 0 (moving +x), then pi/2 (moving +y), and is held while stopped
    assert m["cumulative_heading_changes"] == pytest.approx(math.pi / 2)
    assert m["time_not_moving"] == pytest.approx(2 * DT)


def test_a_step_through_a_wall_is_one_penetration():
    walls = np.array([[2.0, -5.0, 2.0, 5.0]])
    crosser = [(1.0, 0.0), (1.5, 0.0), (2.5, 0.0), (3.0, 0.0)]
    stays = [(1.0, 1.0), (1.9, 1.0), (1.9, 1.5), (1.0, 1.5)]
    traj = Trajectories.from_rows(rows_for({1: crosser, 2: stays}))
    assert wall_penetrations(traj, walls) == (1, 1)
    crowd = crowd_metrics(traj, walls=walls)
    assert crowd["wall_penetrations"] == 1.0
    assert crowd["agents_through_walls"] == 1.0


def test_goal_reach_rate_and_overlaps():
    a = [(0.0, 0.0), (1.0, 0.0), (2.0, 0.0)]
    b = [(0.0, 3.0), (0.0, 3.0), (0.0, 3.0)]
    c = [(2.3, 0.0), (2.3, 0.0), (2.3, 0.0)]  # overlaps with a in the last frame (0.3 apart < 0.6)
    traj = Trajectories.from_rows(rows_for({1: a, 2: b, 3: c}))
    crowd = crowd_metrics(traj, final_goals={1: (2.0, 0.0), 2: (5.0, 5.0), 3: (2.3, 0.0)})
    assert crowd["goal_reach_rate"] == pytest.approx(2 / 3)
    assert crowd["agent_overlaps"] == 1.0


def test_queue_order_violation_and_time_in_queue():
    events = [
        SimEvent(0.0, 1, "queue_join", "pharmacy_counter"),
        SimEvent(1.0, 2, "queue_join", "pharmacy_counter"),
        SimEvent(2.0, 3, "queue_join", "pharmacy_counter"),
        SimEvent(10.0, 1, "queue_served", "pharmacy_counter"),
        SimEvent(20.0, 3, "queue_served", "pharmacy_counter"),  # served before 2: one violation
        SimEvent(30.0, 2, "queue_served", "pharmacy_counter"),
    ]
    q = queue_metrics(events)
    assert q["queue_order_violations"] == 1.0
    assert q["mean_time_in_queue"] == pytest.approx((10 + 18 + 29) / 3)
    assert q["queue_served"] == 3.0


def test_evacuation_completion_and_time():
    a = [(0.0, 0.0), (1.0, 0.0), (2.0, 0.0)]
    b = [(0.0, 1.0), (0.5, 1.0), (1.0, 1.0)]
    traj = Trajectories.from_rows(rows_for({1: a, 2: b}))
    crowd = crowd_metrics(traj, events=[SimEvent(0.2, 1, "evacuated")])
    assert crowd["evacuated"] == 1.0
    assert crowd["evacuation_completion"] == 0.5
    assert crowd["evacuation_time"] == pytest.approx(0.2)


def test_compute_metrics_from_csv_round_trip(tmp_path):
    rows = rows_for({0: [(0.0, 0.0), (1.0, 0.0)], 1: [(3.0, 0.0), (3.0, 0.0)]})
    path = tmp_path / "trajectories.csv"
    lines = ["frame,t,id,x,y,vx,vy,yaw,group"] + [",".join(repr(float(v)) for v in r) for r in rows]
    path.write_text("\n".join(lines) + "\n")
    report = compute_metrics(Trajectories.from_csv(path), robot_goal=(1.0, 0.0))
    assert report.robot["path_length"] == pytest.approx(1.0)
    assert report.crowd["agents"] == 1.0


def test_bad_trajectory_files_are_named(tmp_path):
    with pytest.raises(MetricsError, match="no trajectory file"):
        Trajectories.from_csv(tmp_path / "missing.csv")
    bad = tmp_path / "bad.csv"
    bad.write_text("a,b,c\n1,2,3\n")
    with pytest.raises(MetricsError, match="bad.csv: header"):
        Trajectories.from_csv(bad)


# --------------------------------------------------------------------------- force-based metrics
# hunav_evaluator builds its SFM with lightsfm's defaults: social weight 2.1, obstacle weight 10,
# obstacle sigma 0.2, lambda 2, gamma 0.35, n 2, n' 3.
SOCIAL_WEIGHT = 2.1
OBSTACLE_WEIGHT = 10.0
OBSTACLE_SIGMA = 0.2
LAMBDA, GAMMA, N, N_PRIME = 2.0, 0.35, 2.0, 3.0
FORCE_KEYS = {"social_force_on_agents", "social_force_on_robot", "social_work", "obstacle_force_on_robot",
              "obstacle_force_on_agents"}
GROUP_KEYS = {"group_intimate_space_intrusions", "group_personal_space_intrusions", "group_social_space_intrusions"}


def moussaid_force(p_i, v_i, p_j, v_j) -> np.ndarray:
    """Force on i caused by j, written from the Moussaid model as the evaluator states it: the angle is
    measured from the direction towards j to the interaction direction, and the angular term carries +sign."""
    p_i, v_i, p_j, v_j = (np.asarray(a, dtype=float) for a in (p_i, v_i, p_j, v_j))
    d = float(np.linalg.norm(p_j - p_i))
    towards = (p_j - p_i) / d
    interaction = LAMBDA * (v_i - v_j) + towards
    length = float(np.linalg.norm(interaction))
    unit = interaction / length
    theta = math.atan2(unit[1], unit[0]) - math.atan2(towards[1], towards[0])
    theta = (theta + math.pi) % (2 * math.pi) - math.pi
    b = GAMMA * length
    along = -math.exp(-d / b - (N_PRIME * b * theta) ** 2)
    sideways = np.sign(theta) * math.exp(-d / b - (N * b * theta) ** 2)
    return SOCIAL_WEIGHT * (along * unit + sideways * np.array([-unit[1], unit[0]]))


def test_robot_alone_far_from_walls_feels_no_force():
    robot = [(0.1 * f, 0.0) for f in range(20)]
    walls = np.array([[-20.0, 15.0, 20.0, 15.0], [-20.0, -15.0, 20.0, -15.0]])  # 15 m away: beyond the 10 m search
    traj = Trajectories.from_rows(rows_for({0: robot}))
    m = robot_metrics(traj, walls=walls)
    assert m["social_force_on_robot"] == 0.0
    assert m["social_force_on_agents"] == 0.0
    assert m["obstacle_force_on_robot"] == 0.0
    assert m["social_work"] == 0.0
    assert "obstacle_force_on_agents" not in m  # a mean over nobody: left out, not zero
    assert not GROUP_KEYS & m.keys()


def test_person_walking_head_on_pushes_the_robot_harder_as_the_gap_shrinks():
    # The robot stands at the origin; a person walks at 1 m/s along -x from x=3 to x=1.
    robot = [(0.0, 0.0)] * 21
    person = [(3.0 - 0.1 * f, 0.0) for f in range(21)]
    traj = Trajectories.from_rows(rows_for({0: robot, 1: person}))
    series = force_series(traj.robot, traj.robot_vel, traj.people, traj.people_vel, traj.ids,
                          robot_radius=0.3, person_radius=0.35, walls=np.zeros((0, 4)))
    # Head-on, theta = 0: |F| = w * exp(-d / B) with B = gamma * |lambda * (v_robot - v_person) + e| = 0.35 * 3.
    assert series.social_on_robot[-1] == pytest.approx(SOCIAL_WEIGHT * math.exp(-1.0 / (0.35 * 3.0)))
    assert series.social_on_robot[-1] == pytest.approx(0.81022, abs=1e-5)
    # In frame 0 the person has no recorded velocity yet: B = 0.35 * 1 at d = 3.
    assert series.social_on_robot[0] == pytest.approx(SOCIAL_WEIGHT * math.exp(-3.0 / 0.35))
    assert np.all(np.diff(series.social_on_robot[1:]) > 0)
    expected = [SOCIAL_WEIGHT * math.exp(-(3.0 - 0.1 * f) / (0.35 * (3.0 if f else 1.0))) for f in range(21)]
    m = robot_metrics(traj, walls=np.zeros((0, 4)))
    assert m["social_force_on_robot"] == pytest.approx(sum(expected))
    # The Moussaid force between two people has the same modulus both ways.
    assert m["social_force_on_agents"] == pytest.approx(sum(expected))
    # No wall anywhere: social work is the force on the robot plus the force it causes.
    assert m["social_work"] == pytest.approx(2 * sum(expected))
    assert m["obstacle_force_on_robot"] == 0.0 and m["obstacle_force_on_agents"] == 0.0


def test_social_work_adds_the_forces_on_the_robot_as_vectors():
    # Two people stand 2 m either side of a standing robot: their pushes on it cancel out,
    # while the pushes the robot causes on them add up.
    robot = [(0.0, 0.0)] * 3
    traj = Trajectories.from_rows(rows_for({0: robot, 1: [(0.0, 2.0)] * 3, 2: [(0.0, -2.0)] * 3}))
    m = robot_metrics(traj, walls=np.zeros((0, 4)))
    one = SOCIAL_WEIGHT * math.exp(-2.0 / 0.35)
    assert m["social_force_on_robot"] == pytest.approx(3 * 2 * one)
    assert m["social_force_on_agents"] == pytest.approx(3 * 2 * one)
    assert m["social_work"] == pytest.approx(3 * 2 * one)  # 0 on the robot + 2 caused, per frame


def test_social_forces_match_the_moussaid_formula_in_random_crossings():
    rng = np.random.default_rng(7)
    frames, people = 6, 4
    robot = rng.uniform(-3, 3, (frames, 3))
    robot_vel = rng.uniform(-1, 1, (frames, 2))
    pos = rng.uniform(-3, 3, (frames, people, 2))
    vel = rng.uniform(-1.2, 1.2, (frames, people, 2))
    series = force_series(robot, robot_vel, pos, vel, np.arange(1, people + 1), robot_radius=0.3,
                          person_radius=0.35, walls=np.zeros((0, 4)))
    for f in range(frames):
        on_robot = [moussaid_force(robot[f, :2], robot_vel[f], pos[f, k], vel[f, k]) for k in range(people)]
        caused = [moussaid_force(pos[f, k], vel[f, k], robot[f, :2], robot_vel[f]) for k in range(people)]
        assert series.social_on_robot[f] == pytest.approx(sum(np.linalg.norm(v) for v in on_robot), rel=1e-9)
        assert series.social_on_agents[f] == pytest.approx(sum(np.linalg.norm(v) for v in caused), rel=1e-9)
        assert series.social_work[f] == pytest.approx(
            np.linalg.norm(np.sum(on_robot, axis=0)) + sum(np.linalg.norm(v) for v in caused), rel=1e-9)


def test_robot_passing_a_wall_feels_the_nearest_point_only():
    # The robot drives along y=0 past a wall at y=1; a farther wall at y=-1.2 must not add to it
    # (the evaluator uses the closest obstacle point, unlike the simulator's sum over walls).
    walls = np.array([[-10.0, 1.0, 10.0, 1.0], [-10.0, -1.2, 10.0, -1.2]])
    robot = [(0.2 * f, 0.0) for f in range(10)]
    person = [(0.0, -0.7)] * 10  # 0.5 m from the lower wall, 1.7 m from the upper one
    traj = Trajectories.from_rows(rows_for({0: robot, 1: person}))
    m = robot_metrics(traj, robot_radius=0.3, person_radius=0.35, walls=walls)
    on_robot = OBSTACLE_WEIGHT * math.exp(-(1.0 - 0.3) / OBSTACLE_SIGMA)  # 10 exp(-3.5) = 0.302
    assert m["obstacle_force_on_robot"] == pytest.approx(10 * on_robot)
    assert m["obstacle_force_on_robot"] == pytest.approx(3.0197, abs=1e-4)
    on_person = OBSTACLE_WEIGHT * math.exp(-(0.5 - 0.35) / OBSTACLE_SIGMA)
    assert m["obstacle_force_on_agents"] == pytest.approx(10 * on_person)  # mean over the one person, per frame
    assert m["social_work"] == pytest.approx(m["social_force_on_robot"] + m["social_force_on_agents"]
                                             + m["obstacle_force_on_robot"])  # one person: vector sum = modulus
    without_walls = robot_metrics(traj)
    assert not {"obstacle_force_on_robot", "obstacle_force_on_agents", "social_work"} & without_walls.keys()
    assert without_walls["social_force_on_robot"] == pytest.approx(m["social_force_on_robot"])


def test_obstacle_force_on_agents_is_a_mean_over_the_people_present():
    walls = np.array([[-10.0, 1.0, 10.0, 1.0]])
    robot = [(0.0, -20.0)] * 2  # out of everyone's way and beyond the wall search
    near = [(0.0, 0.5)] * 2
    far = [(5.0, -1.0)] * 2
    traj = Trajectories.from_rows(rows_for({0: robot, 1: near, 2: far}))
    m = robot_metrics(traj, walls=walls)
    per_frame = (OBSTACLE_WEIGHT * math.exp(-(0.5 - 0.35) / OBSTACLE_SIGMA)
                 + OBSTACLE_WEIGHT * math.exp(-(2.0 - 0.35) / OBSTACLE_SIGMA)) / 2
    assert m["obstacle_force_on_agents"] == pytest.approx(2 * per_frame)
    assert m["obstacle_force_on_robot"] == 0.0


# --------------------------------------------------------------------------- group space intrusions


def side_by_side(robot_offset: float, frames: int = 10) -> np.ndarray:
    """Two people walking +x at 1 m/s at y = +-0.5 (group 1); the robot keeps pace `robot_offset` m ahead
    of the midpoint between them. Their interaction centre is 1.5 m ahead of that midpoint."""
    a = [(0.1 * f, 0.5) for f in range(frames)]
    b = [(0.1 * f, -0.5) for f in range(frames)]
    robot = [(0.1 * f + robot_offset, 0.0) for f in range(frames)]
    return rows_for({0: robot, 1: a, 2: b}, group={1: 1, 2: 1})


@pytest.mark.parametrize("robot_offset, band", [
    (1.0, "intimate"),   # 0.5 m from the interaction centre, minus the robot's 0.3 m radius: 0.2
    (2.5, "personal"),   # 1.0 - 0.3 = 0.7
    (-1.0, "social"),    # behind the pair: 2.5 - 0.3 = 2.2
    (-4.5, "public"),    # 6.0 - 0.3 = 5.7: no band
])
def test_robot_in_front_of_a_walking_pair_intrudes_the_groups_space_by_band(robot_offset, band):
    traj = Trajectories.from_rows(side_by_side(robot_offset))
    m = group_space_intrusions(traj, robot_radius=0.3)
    expected = {f"group_{b}_space_intrusions": 100.0 if b == band else 0.0 for b in ("intimate", "personal", "social")}
    assert m == pytest.approx(expected)
    assert {k: v for k, v in robot_metrics(traj).items() if k in GROUP_KEYS} == pytest.approx(expected)


def test_group_centre_follows_the_members_yaw_while_they_stand():
    # A conversing pair at (0, 0) facing +x and (1, 0) facing -x: points 1.5 m ahead are (1.5, 0) and
    # (-0.5, 0), so the interaction centre is (0.5, 0). The robot stands 0.6 m beside it: 0.3 m -> intimate.
    rows = []
    for f in range(4):
        rows.append([f, f * DT, 0, 0.5, 0.6, 0.0, 0.0, 0.0, -1])
        rows.append([f, f * DT, 1, 0.0, 0.0, 0.0, 0.0, 0.0, 4])
        rows.append([f, f * DT, 2, 1.0, 0.0, 0.0, 0.0, math.pi, 4])
    traj = Trajectories.from_rows(np.asarray(rows, dtype=float))
    m = group_space_intrusions(traj, robot_radius=0.3)
    assert m["group_intimate_space_intrusions"] == pytest.approx(100.0)


def test_group_membership_comes_from_the_caller_when_given():
    rows = side_by_side(1.0)
    rows[:, 8] = -1  # nothing recorded as a group
    traj = Trajectories.from_rows(rows)
    assert group_space_intrusions(traj) == {}
    assert not GROUP_KEYS & robot_metrics(traj).keys()
    m = group_space_intrusions(traj, groups={1: 3, 2: 3})
    assert m["group_intimate_space_intrusions"] == pytest.approx(100.0)
    report = compute_metrics(traj, groups={1: 3, 2: 3})
    assert report.robot["group_intimate_space_intrusions"] == pytest.approx(100.0)
    # Two groups of one each: the centres are 1.5 m ahead of each person; the nearer one counts.
    split = group_space_intrusions(traj, groups={1: 3, 2: 5})
    gap = math.hypot(1.5 - 1.0, 0.5) - 0.3  # 0.407
    assert split["group_intimate_space_intrusions"] == pytest.approx(100.0 if gap < 0.45 else 0.0)


def test_group_intrusions_count_every_robot_frame_in_the_share():
    # The pair leaves (absent rows) after 4 of 10 frames: frames without a group count as no intrusion.
    rows = side_by_side(1.0)
    keep = (rows[:, 2] == 0) | (rows[:, 0] < 4)
    traj = Trajectories.from_rows(rows[keep])
    m = group_space_intrusions(traj, robot_radius=0.3)
    assert m["group_intimate_space_intrusions"] == pytest.approx(40.0)


def test_runs_without_a_robot_have_no_robot_force_or_group_metrics():
    a = [(0.1 * f, 0.5) for f in range(5)]
    b = [(0.1 * f, -0.5) for f in range(5)]
    traj = Trajectories.from_rows(rows_for({1: a, 2: b}, group={1: 1, 2: 1}))
    report = compute_metrics(traj, walls=np.array([[-5.0, 1.0, 5.0, 1.0]]), groups={1: 1, 2: 1})
    assert report.robot == {}
    assert group_space_intrusions(traj) == {}
