"""Metrics on hand-built trajectories whose answers are known exactly."""

from __future__ import annotations

import math

import numpy as np
import pytest

from grove_tui.engine.metrics import (
    MetricsError,
    SimEvent,
    Trajectories,
    compute_metrics,
    crowd_metrics,
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
