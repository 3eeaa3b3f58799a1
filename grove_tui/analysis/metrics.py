"""Metrics of a simulated scenario: HuNavSim evaluator's robot metrics and crowd plausibility metrics.

Inputs are the recorded trajectories (columns frame, t, id, x, y, vx, vy, yaw, group; the robot is id 0),
optionally the world's wall segments, the agents' groups, their final goals and the simulation's event log.
The evaluator's force-based metrics (social force, obstacle force, social work) live in force_metrics.py.
Distances between bodies are centre distance minus both radii, clamped at 0 (as hunav_evaluator does).
"""

from __future__ import annotations

import csv
import math
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from grove_tui.errors import MetricsError
from grove_tui.scenario.events import SimEvent
from grove_tui.analysis.force_metrics import force_metrics, force_series

INTIMATE = 0.45
PERSONAL = 1.2
SOCIAL = 3.6
COLLISION_GAP = 0.02
# HuNavSim places a group's interaction centre at the mean of points this far ahead of its members.
GROUP_CENTRE_AHEAD = 1.5
ROBOT_ID = 0


@dataclass(frozen=True)
class Trajectories:
    """Positions on a common frame axis: people (F, N, 2) with NaN where an agent is absent."""

    t: np.ndarray  # (F,)
    ids: np.ndarray  # (N,) person ids, robot excluded
    people: np.ndarray  # (F, N, 2)
    people_vel: np.ndarray  # (F, N, 2)
    people_yaw: np.ndarray  # (F, N) NaN where absent
    groups: np.ndarray  # (N,) as recorded in each agent's last row
    robot: np.ndarray | None  # (F, 3) x, y, yaw
    robot_vel: np.ndarray | None  # (F, 2)

    @property
    def frames(self) -> int:
        return int(self.t.shape[0])

    @classmethod
    def from_rows(cls, rows: np.ndarray) -> Trajectories:
        """rows: (R, 9) frame, t, id, x, y, vx, vy, yaw, group."""
        if rows.ndim != 2 or rows.shape[1] != 9:
            raise MetricsError(f"trajectory rows must have 9 columns, got shape {rows.shape}")
        if rows.shape[0] == 0:
            raise MetricsError("no trajectory rows")
        frames, frame_index = np.unique(rows[:, 0].astype(np.int64), return_inverse=True)
        t = np.zeros(frames.size)
        t[frame_index] = rows[:, 1]
        person_rows = rows[:, 2] != ROBOT_ID
        ids = np.unique(rows[person_rows, 2].astype(np.int64))
        column = {int(i): k for k, i in enumerate(ids)}
        people = np.full((frames.size, ids.size, 2), np.nan)
        people_vel = np.full((frames.size, ids.size, 2), np.nan)
        people_yaw = np.full((frames.size, ids.size), np.nan)
        groups = np.full(ids.size, -1, dtype=np.int64)
        robot = None
        robot_vel = None
        if (~person_rows).any():
            robot = np.full((frames.size, 3), np.nan)
            robot_vel = np.full((frames.size, 2), np.nan)
            r = rows[~person_rows]
            fi = frame_index[~person_rows]
            robot[fi] = r[:, [3, 4, 7]]
            robot_vel[fi] = r[:, [5, 6]]
        p = rows[person_rows]
        fi = frame_index[person_rows]
        cols = np.array([column[int(i)] for i in p[:, 2]], dtype=np.int64)
        people[fi, cols] = p[:, 3:5]
        people_vel[fi, cols] = p[:, 5:7]
        people_yaw[fi, cols] = p[:, 7]
        groups[cols] = p[:, 8].astype(np.int64)
        return cls(t=t, ids=ids, people=people, people_vel=people_vel, people_yaw=people_yaw, groups=groups,
                   robot=robot, robot_vel=robot_vel)

    @classmethod
    def from_csv(cls, path: str | Path) -> Trajectories:
        path = Path(path)
        try:
            with path.open(newline="", encoding="utf-8") as handle:
                reader = csv.reader(handle)
                header = next(reader)
                expected = ["frame", "t", "id", "x", "y", "vx", "vy", "yaw", "group"]
                if [h.strip() for h in header] != expected:
                    raise MetricsError(f"{path}: header must be {','.join(expected)}, got {','.join(header)}")
                rows = np.array([[float(v) for v in row] for row in reader if row], dtype=np.float64)
        except FileNotFoundError:
            raise MetricsError(f"{path}: no trajectory file (simulate the bundle first)") from None
        except (StopIteration, ValueError) as exc:
            raise MetricsError(f"{path}: not a trajectory CSV: {exc}") from None
        if rows.size == 0:
            raise MetricsError(f"{path}: no trajectory rows")
        return cls.from_rows(rows)


@dataclass
class MetricsReport:
    robot: dict[str, float] = field(default_factory=dict)
    crowd: dict[str, float] = field(default_factory=dict)

    def to_dict(self) -> dict[str, dict[str, float]]:
        return {"robot": dict(self.robot), "crowd": dict(self.crowd)}


def _wrap(angle: np.ndarray) -> np.ndarray:
    return (angle + np.pi) % (2 * np.pi) - np.pi


def _step_lengths(points: np.ndarray) -> np.ndarray:
    d = np.diff(points, axis=0)
    lengths = np.hypot(d[:, 0], d[:, 1])
    return np.where(np.isfinite(lengths), lengths, 0.0)


def robot_metrics(
    traj: Trajectories,
    *,
    robot_radius: float = 0.3,
    person_radius: float | np.ndarray = 0.35,
    goal: Sequence[float] | None = None,
    goal_radius: float = 0.3,
    walls: np.ndarray | None = None,
    groups: Mapping[int, int] | None = None,
) -> dict[str, float]:
    """HuNavSim evaluator metrics for the robot (hunav_evaluator/hunav_metrics.py 2.0).

    `walls` (M, 4) are the obstacles of the force metrics (see force_metrics.py); without them the
    obstacle forces and social work are left out. `groups` maps agent id -> group id for the group
    space intrusions (see `group_space_intrusions`).
    """
    if traj.robot is None:
        return {}
    valid = np.isfinite(traj.robot[:, 0])
    if not valid.any():
        return {}
    t = traj.t[valid]
    pose = traj.robot[valid]
    vel = traj.robot_vel[valid] if traj.robot_vel is not None else np.zeros((t.size, 2))
    people = traj.people[valid]
    people_vel = traj.people_vel[valid]
    out: dict[str, float] = {}

    out["path_length"] = float(_step_lengths(pose[:, :2]).sum())
    out["cumulative_heading_changes"] = float(np.abs(_wrap(np.diff(pose[:, 2]))).sum())
    dt = np.diff(t)
    mean_dt = float(dt.mean()) if dt.size else 0.0
    speed = np.hypot(vel[:, 0], vel[:, 1])
    angular = np.abs(_wrap(np.diff(pose[:, 2]))) / np.where(dt > 0, dt, np.inf) if dt.size else np.zeros(0)
    out["avg_robot_linear_speed"] = float(speed.mean())
    out["avg_robot_angular_speed"] = float(angular.mean()) if angular.size else 0.0
    if dt.size:
        safe_dt = np.where(dt > 0, dt, np.inf)
        accel = np.hypot(*np.diff(vel, axis=0).T) / safe_dt
        out["avg_acceleration"] = float(accel.mean())
        over = np.abs(np.diff(accel)) / safe_dt[1:] if accel.size > 1 else np.zeros(1)
        out["avg_overacceleration"] = float(over.mean())
        not_moving = (speed[1:] < 0.01) & (angular < 0.02)
        out["time_not_moving"] = float(not_moving.sum() * mean_dt)
    else:
        out["avg_acceleration"] = 0.0
        out["avg_overacceleration"] = 0.0
        out["time_not_moving"] = 0.0

    if goal is not None:
        gx, gy = float(goal[0]), float(goal[1])
        dist_goal = np.hypot(pose[:, 0] - gx, pose[:, 1] - gy)
        reached = np.nonzero(dist_goal - goal_radius < 0.3)[0]
        out["completed"] = float(reached.size > 0)
        end = reached[0] if reached.size else t.size - 1
        out["time_to_reach_goal"] = float(t[end] - t[0])
        out["minimum_distance_to_target"] = float(dist_goal.min())
        out["final_distance_to_target"] = float(dist_goal[-1])
    else:
        out["time_to_reach_goal"] = float(t[-1] - t[0])

    radii = np.broadcast_to(np.asarray(person_radius, dtype=float), (traj.ids.size,))
    centre = np.hypot(people[:, :, 0] - pose[:, None, 0], people[:, :, 1] - pose[:, None, 1])
    gap = np.clip(centre - radii[None, :] - robot_radius, 0.0, None)
    gap = np.where(np.isfinite(gap), gap, np.inf)
    closest = gap.min(axis=1) if traj.ids.size else np.full(t.size, np.inf)
    seen = np.isfinite(closest)
    if seen.any():
        out["avg_distance_to_closest_person"] = float(closest[seen].mean())
        out["minimum_distance_to_people"] = float(closest[seen].min())
        finite_gaps = gap[np.isfinite(gap)]
        out["maximum_distance_to_people"] = float(finite_gaps.max())
        out.update(_space_intrusions(closest, prefix=""))
        nearest = np.argmin(gap, axis=1)
        nearest_vel = people_vel[np.arange(t.size), nearest]
        out["avg_closest_pedestrian_velocity"] = float(np.nanmean(np.hypot(nearest_vel[:, 0], nearest_vel[:, 1])))
        robot_hits, person_hits = _collisions(pose, vel, people, people_vel, gap)
        out["robot_on_person_collision"] = float(robot_hits)
        out["person_on_robot_collision"] = float(person_hits)
    ped_speed = np.hypot(people_vel[:, :, 0], people_vel[:, :, 1])
    out["avg_pedestrian_velocity"] = float(np.nanmean(ped_speed)) if np.isfinite(ped_speed).any() else 0.0
    out.update(group_space_intrusions(traj, robot_radius=robot_radius, groups=groups))
    out.update(force_metrics(force_series(pose, vel, people, people_vel, traj.ids, robot_radius=robot_radius,
                                          person_radius=radii, walls=walls)))
    return out


def _space_intrusions(closest: np.ndarray, prefix: str) -> dict[str, float]:
    """Share of frames (%) whose closest distance falls in the intimate, personal and social bands.

    Every frame counts in the denominator, including frames where nothing was near (distance inf).
    """
    n = float(closest.size)
    return {
        f"{prefix}intimate_space_intrusions": float(100.0 * (closest < INTIMATE).sum() / n),
        f"{prefix}personal_space_intrusions": float(100.0 * ((closest >= INTIMATE) & (closest < PERSONAL)).sum() / n),
        f"{prefix}social_space_intrusions": float(100.0 * ((closest >= PERSONAL) & (closest < SOCIAL)).sum() / n),
    }


def group_space_intrusions(
    traj: Trajectories,
    *,
    robot_radius: float = 0.3,
    groups: Mapping[int, int] | None = None,
) -> dict[str, float]:
    """HuNavSim's group_{intimate,personal,social}_space_intrusions: % of the robot's frames whose
    distance to the nearest group's interaction centre falls in the 0.45 / 1.2 / 3.6 m bands.

    A group's interaction centre is the mean of the points GROUP_CENTRE_AHEAD (1.5 m) ahead of each
    member present in the frame, along the member's recorded yaw. The distance is from the robot's
    centre to that point minus the robot's radius, clamped at 0 like the body distances; no person
    radius is subtracted, the centre being a point in front of the group rather than a body.

    `groups` maps agent id -> group id (-1 for none); bundles pass the scenario's groups, which
    like HuNavSim's configured group_id do not change while behaviours run. Without it, the group
    recorded in each agent's last trajectory row is used.

    With no group, or no member of one ever present while the robot was, the keys are left out,
    as the person intrusions are when nobody is seen (the evaluator reports 0 % without groups).
    """
    if traj.robot is None:
        return {}
    valid = np.isfinite(traj.robot[:, 0])
    if groups is None:
        membership = traj.groups
    else:
        membership = np.array([groups.get(int(agent_id), -1) for agent_id in traj.ids], dtype=np.int64)
    group_ids = np.unique(membership[membership >= 0])
    if not valid.any() or group_ids.size == 0:
        return {}
    robot = traj.robot[valid, :2]
    people = traj.people[valid]
    yaw = traj.people_yaw[valid]
    ahead = people + GROUP_CENTRE_AHEAD * np.stack([np.cos(yaw), np.sin(yaw)], axis=-1)
    nearest = np.full(robot.shape[0], np.inf)
    for group in group_ids:
        points = ahead[:, membership == group]
        present = np.isfinite(points[:, :, 0]) & np.isfinite(points[:, :, 1])
        count = present.sum(axis=1)
        summed = np.where(present[:, :, None], points, 0.0).sum(axis=1)
        centre = summed / np.maximum(count, 1)[:, None]
        distance = np.clip(np.hypot(*(robot - centre).T) - robot_radius, 0.0, None)
        nearest = np.minimum(nearest, np.where(count > 0, distance, np.inf))
    if not np.isfinite(nearest).any():
        return {}
    return _space_intrusions(nearest, prefix="group_")


def _collisions(pose: np.ndarray, vel: np.ndarray, people: np.ndarray, people_vel: np.ndarray,
                gap: np.ndarray) -> tuple[int, int]:
    """Count collision onsets (gap < 2 cm), blamed on whoever moves toward the other (evaluator's rule)."""
    touching = gap < COLLISION_GAP
    onset = touching.copy()
    onset[1:] &= ~touching[:-1]
    robot_hits = person_hits = 0
    for f, j in zip(*np.nonzero(onset), strict=True):
        to_person = people[f, j] - pose[f, :2]
        robot_push = float(np.dot(vel[f], to_person))
        person_push = float(np.dot(people_vel[f, j], -to_person))
        if robot_push >= person_push:
            robot_hits += 1
        else:
            person_hits += 1
    return robot_hits, person_hits


def _segments_cross(p: np.ndarray, q: np.ndarray, walls: np.ndarray) -> np.ndarray:
    """For motion segments p->q (K,2) and walls (M,4): (K,) whether each motion properly crosses any wall."""
    if walls.size == 0 or p.size == 0:
        return np.zeros(p.shape[0], dtype=bool)
    a = walls[None, :, 0:2]
    b = walls[None, :, 2:4]
    p_ = p[:, None, :]
    q_ = q[:, None, :]

    def orient(u: np.ndarray, v: np.ndarray, w: np.ndarray) -> np.ndarray:
        return (v[..., 0] - u[..., 0]) * (w[..., 1] - u[..., 1]) - (v[..., 1] - u[..., 1]) * (w[..., 0] - u[..., 0])

    d1 = orient(a, b, p_)
    d2 = orient(a, b, q_)
    d3 = orient(p_, q_, a)
    d4 = orient(p_, q_, b)
    crosses = (d1 * d2 < 0) & (d3 * d4 < 0)
    return crosses.any(axis=1)


def wall_penetrations(traj: Trajectories, walls: np.ndarray) -> tuple[int, int]:
    """(crossing steps, agents that ever crossed): every recorded step whose motion crosses a wall segment."""
    walls = np.asarray(walls, dtype=float).reshape(-1, 4)
    total = 0
    agents = 0
    for k in range(traj.ids.size):
        pts = traj.people[:, k]
        ok = np.isfinite(pts[:, 0])
        pts = pts[ok]
        if pts.shape[0] < 2:
            continue
        # Only test steps that could reach a wall: the walls' bounding boxes are cheap to pre-filter.
        crossing = _segments_cross(pts[:-1], pts[1:], walls)
        count = int(crossing.sum())
        total += count
        agents += int(count > 0)
    return total, agents


def agent_overlaps(traj: Trajectories, radius: float = 0.35, tolerance: float = 0.1) -> int:
    """Frames x pairs where two people's bodies overlap by more than `tolerance` metres."""
    count = 0
    limit = 2 * radius - tolerance
    for f in range(traj.frames):
        pts = traj.people[f]
        pts = pts[np.isfinite(pts[:, 0])]
        if pts.shape[0] < 2:
            continue
        d = np.hypot(pts[:, None, 0] - pts[None, :, 0], pts[:, None, 1] - pts[None, :, 1])
        iu = np.triu_indices(pts.shape[0], k=1)
        count += int((d[iu] < limit).sum())
    return count


def queue_metrics(events: Iterable[SimEvent]) -> dict[str, float]:
    """Time in queue and order violations: being served before someone who joined the same queue earlier."""
    joins: dict[str, list[tuple[float, int]]] = {}
    served: dict[str, list[tuple[float, int]]] = {}
    for e in events:
        if e.kind == "queue_join":
            joins.setdefault(e.detail, []).append((e.t, e.agent_id))
        elif e.kind == "queue_served":
            served.setdefault(e.detail, []).append((e.t, e.agent_id))
    if not joins:
        return {}
    waits: list[float] = []
    violations = 0
    for name, joined in joins.items():
        join_time = {a: t for t, a in sorted(joined)}
        join_rank = {a: r for r, (_, a) in enumerate(sorted(joined))}
        done = sorted(served.get(name, []))
        for t, a in done:
            if a in join_time:
                waits.append(t - join_time[a])
        ranks = [join_rank[a] for _, a in done if a in join_rank]
        violations += sum(1 for i in range(len(ranks)) for j in range(i + 1, len(ranks)) if ranks[i] > ranks[j])
    return {
        "queue_members": float(sum(len(v) for v in joins.values())),
        "queue_served": float(sum(len(v) for v in served.values())),
        "mean_time_in_queue": float(np.mean(waits)) if waits else math.nan,
        "queue_order_violations": float(violations),
    }


def crowd_metrics(
    traj: Trajectories,
    *,
    walls: np.ndarray | None = None,
    final_goals: Mapping[int, Sequence[float]] | None = None,
    goal_tolerance: float = 0.6,
    events: Sequence[SimEvent] = (),
    walkable_area: float | None = None,
    radius: float = 0.35,
) -> dict[str, float]:
    out: dict[str, float] = {"agents": float(traj.ids.size), "duration": float(traj.t[-1] - traj.t[0])}
    if walls is not None:
        steps, agents = wall_penetrations(traj, walls)
        out["wall_penetrations"] = float(steps)
        out["agents_through_walls"] = float(agents)
    out["agent_overlaps"] = float(agent_overlaps(traj, radius=radius))
    evacuated = {e.agent_id: e.t for e in events if e.kind == "evacuated"}
    if final_goals:
        reached = 0
        for k, agent_id in enumerate(traj.ids):
            goal = final_goals.get(int(agent_id))
            if goal is None:
                continue
            if int(agent_id) in evacuated:
                reached += 1
                continue
            pts = traj.people[:, k]
            pts = pts[np.isfinite(pts[:, 0])]
            if pts.size and np.hypot(*(pts - np.asarray(goal, dtype=float)).T).min() <= goal_tolerance:
                reached += 1
        counted = sum(1 for a in traj.ids if int(a) in final_goals)
        out["goal_reach_rate"] = reached / counted if counted else math.nan
    if evacuated or any(e.kind == "evacuated" for e in events):
        out["evacuated"] = float(len(evacuated))
        out["evacuation_completion"] = len(evacuated) / traj.ids.size if traj.ids.size else math.nan
        out["evacuation_time"] = float(max(evacuated.values()) - traj.t[0]) if evacuated else math.nan
    out.update(queue_metrics(events))
    speed = np.hypot(traj.people_vel[:, :, 0], traj.people_vel[:, :, 1])
    out["mean_speed"] = float(np.nanmean(speed)) if np.isfinite(speed).any() else 0.0
    present = np.isfinite(traj.people[:, :, 0]).sum(axis=1)
    if walkable_area:
        out["mean_density"] = float(present.mean() / walkable_area)
    out["peak_local_density"] = _peak_local_density(traj)
    return out


def _peak_local_density(traj: Trajectories, cell: float = 2.0) -> float:
    """Highest number of people per m² in any 2 m x 2 m cell at any frame."""
    best = 0
    for f in range(traj.frames):
        pts = traj.people[f]
        pts = pts[np.isfinite(pts[:, 0])]
        if pts.size == 0:
            continue
        keys = np.floor(pts / cell).astype(np.int64)
        _, counts = np.unique(keys, axis=0, return_counts=True)
        best = max(best, int(counts.max()))
    return best / (cell * cell)


def compute_metrics(
    traj: Trajectories,
    *,
    walls: np.ndarray | None = None,
    robot_goal: Sequence[float] | None = None,
    robot_radius: float = 0.3,
    person_radius: float = 0.35,
    final_goals: Mapping[int, Sequence[float]] | None = None,
    events: Sequence[SimEvent] = (),
    walkable_area: float | None = None,
    groups: Mapping[int, int] | None = None,
) -> MetricsReport:
    return MetricsReport(
        robot=robot_metrics(traj, robot_radius=robot_radius, person_radius=person_radius, goal=robot_goal,
                            walls=walls, groups=groups),
        crowd=crowd_metrics(traj, walls=walls, final_goals=final_goals, events=events,
                            walkable_area=walkable_area, radius=person_radius),
    )
