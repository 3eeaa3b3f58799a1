"""Metrics of a simulated scenario: HuNavSim evaluator's robot metrics and crowd plausibility metrics.

Inputs are the recorded trajectories (columns frame, t, id, x, y, vx, vy, yaw, group; the robot is id 0),
optionally the world's wall segments, the agents' groups, their final goals and the simulation's event log.
The evaluator's force-based metrics (social force, obstacle force, social work) live in force_metrics.py.
Distances between bodies are centre distance minus both radii, clamped at 0 (as hunav_evaluator does).
"""

from __future__ import annotations

import csv
import math
from collections.abc import Iterable, Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import TypedDict, Unpack

import numpy as np

from grove_tui.errors import MetricsError
from grove_tui.scenario.events import SimEvent
from grove_tui.analysis.force_metrics import ForceSeries, force_metrics, force_series

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
        """The whole file in memory; `iter_trajectory_chunks` reads it a block of frames at a time."""
        blocks = list(iter_row_blocks(path))
        return cls.from_rows(np.concatenate(blocks) if len(blocks) > 1 else blocks[0])

    @classmethod
    def from_rows_on(cls, rows: np.ndarray, ids: np.ndarray, groups: np.ndarray) -> Trajectories:
        """Rows laid out on a given id axis (a chunk of a longer run: every chunk shares one axis)."""
        frames, frame_index = np.unique(rows[:, 0].astype(np.int64), return_inverse=True)
        t = np.zeros(frames.size)
        t[frame_index] = rows[:, 1]
        person_rows = rows[:, 2] != ROBOT_ID
        people = np.full((frames.size, ids.size, 2), np.nan)
        people_vel = np.full((frames.size, ids.size, 2), np.nan)
        people_yaw = np.full((frames.size, ids.size), np.nan)
        robot = robot_vel = None
        if (~person_rows).any():
            robot = np.full((frames.size, 3), np.nan)
            robot_vel = np.full((frames.size, 2), np.nan)
            r = rows[~person_rows]
            fi = frame_index[~person_rows]
            robot[fi] = r[:, [3, 4, 7]]
            robot_vel[fi] = r[:, [5, 6]]
        p = rows[person_rows]
        fi = frame_index[person_rows]
        cols = np.searchsorted(ids, p[:, 2].astype(np.int64))
        people[fi, cols] = p[:, 3:5]
        people_vel[fi, cols] = p[:, 5:7]
        people_yaw[fi, cols] = p[:, 7]
        return cls(t=t, ids=ids, people=people, people_vel=people_vel, people_yaw=people_yaw, groups=groups.copy(),
                   robot=robot, robot_vel=robot_vel)


TRAJECTORY_COLUMNS = ["frame", "t", "id", "x", "y", "vx", "vy", "yaw", "group"]
# Rows parsed per block: 250,000 rows (500 frames of 500 people) keep the metrics step's peak near
# 0.5 GB with the hospital's walls whatever the run's length (bench/metrics_memory.py).
ROWS_PER_BLOCK = 250_000


def iter_row_blocks(path: str | Path, rows_per_block: int = ROWS_PER_BLOCK,
                    in_frame_order: bool = False) -> Iterator[np.ndarray]:
    """(R, 9) float64 blocks of a trajectories.csv, checked as they are read: the header, that every
    value is a finite number (a NaN row names its line) and, with `in_frame_order`, that frame
    numbers never go backwards (which streaming by frames needs)."""
    import pandas as pd

    path = Path(path)
    try:
        with path.open(newline="", encoding="utf-8") as handle:
            header = next(csv.reader(handle), None)
    except FileNotFoundError:
        raise MetricsError(f"{path}: no trajectory file (simulate the bundle first)") from None
    except (OSError, UnicodeDecodeError, csv.Error) as exc:
        raise MetricsError(f"{path}: not a trajectory CSV: {exc}") from None
    if header is None:
        raise MetricsError(f"{path}: not a trajectory CSV: the file is empty")
    if [h.strip() for h in header] != TRAJECTORY_COLUMNS:
        raise MetricsError(f"{path}: header must be {','.join(TRAJECTORY_COLUMNS)}, got {','.join(header)}")
    first_line = 2
    last_frame = -math.inf
    any_rows = False
    try:
        reader = pd.read_csv(path, chunksize=rows_per_block, dtype=np.float64, skip_blank_lines=True,
                             engine="c", na_filter=True)
        for frame in reader:
            if frame.shape[1] != 9:
                raise MetricsError(f"{path}: rows must have 9 columns, got {frame.shape[1]}")
            rows = frame.to_numpy(dtype=np.float64, copy=False)
            bad = ~np.isfinite(rows).all(axis=1)
            if bad.any():
                line = first_line + int(np.flatnonzero(bad)[0])
                raise MetricsError(f"{path}:{line}: a value is missing or not a finite number")
            if in_frame_order:
                backwards = np.flatnonzero(np.diff(rows[:, 0], prepend=last_frame) < 0)
                if backwards.size:
                    raise MetricsError(f"{path}:{first_line + int(backwards[0])}: frame numbers go backwards; "
                                       f"streamed metrics need rows in frame order, as the simulation writes them")
            if rows.size:
                any_rows = True
                last_frame = float(rows[-1, 0])
                first_line += rows.shape[0]
                yield rows
    except (ValueError, pd.errors.ParserError, pd.errors.EmptyDataError, UnicodeDecodeError, OSError) as exc:
        raise MetricsError(f"{path}: not a trajectory CSV: {str(exc).splitlines()[0][:200]}") from None
    if not any_rows:
        raise MetricsError(f"{path}: no trajectory rows")


def iter_trajectory_chunks(path: str | Path, rows_per_block: int = ROWS_PER_BLOCK
                           ) -> tuple[np.ndarray, np.ndarray, Iterator[Trajectories]]:
    """(person ids, each one's last recorded group, chunks of whole frames on that id axis).

    A first pass reads only the id and group columns (what `Trajectories.from_rows` takes from the
    whole file); the second yields the frames a block at a time, a frame never split across chunks.
    """
    last_group: dict[int, int] = {}
    for rows in iter_row_blocks(path, rows_per_block):
        people = rows[rows[:, 2] != ROBOT_ID]
        # Later rows overwrite earlier ones: each agent keeps the group of its last row.
        last_group.update(zip(people[:, 2].astype(np.int64).tolist(), people[:, 8].astype(np.int64).tolist()))
    ids = np.array(sorted(last_group), dtype=np.int64)
    groups = np.array([last_group[int(i)] for i in ids], dtype=np.int64)

    def chunks() -> Iterator[Trajectories]:
        pending = np.zeros((0, 9))
        for rows in iter_row_blocks(path, rows_per_block, in_frame_order=True):
            rows = np.concatenate([pending, rows]) if pending.size else rows
            # The last frame of a block may continue in the next one: hold it back.
            cut = int(np.searchsorted(rows[:, 0], rows[-1, 0], side="left"))
            pending = rows[cut:]
            if cut:
                yield Trajectories.from_rows_on(rows[:cut], ids, groups)
        if pending.size:
            yield Trajectories.from_rows_on(pending, ids, groups)

    return ids, groups, chunks()


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
    space intrusions (see `group_space_intrusions`). The run is measured as one chunk of
    `RobotAccumulator`, the same code that streams a long run's CSV.
    """
    accumulator = RobotAccumulator(traj.ids, robot_radius=robot_radius, person_radius=person_radius, goal=goal,
                                   goal_radius=goal_radius, walls=walls, groups=groups)
    accumulator.add(traj)
    return accumulator.result()


class RobotAccumulator:
    """The robot metrics over a run fed one chunk of consecutive frames at a time.

    Per frame it keeps only scalars (the robot's pose and speed, the closest gap, the force moduli):
    a few dozen bytes a frame whatever the crowd's size, so a one-hour run of 500 people is measured
    in a few hundred MB instead of the 4 GB its dense (frames x people) arrays took. Every per-frame
    value is computed exactly as on the whole run; only the two means over people x frames
    (pedestrian speed) are summed chunk by chunk.
    """

    def __init__(self, ids: np.ndarray, *, robot_radius: float = 0.3, person_radius: float | np.ndarray = 0.35,
                 goal: Sequence[float] | None = None, goal_radius: float = 0.3, walls: np.ndarray | None = None,
                 groups: Mapping[int, int] | None = None) -> None:
        self.ids = np.asarray(ids, dtype=np.int64)
        self.robot_radius = float(robot_radius)
        self.person_radius = person_radius
        self.radii = np.broadcast_to(np.asarray(person_radius, dtype=float), (self.ids.size,))
        self.goal = goal
        self.goal_radius = goal_radius
        self.walls = walls
        self.groups = groups
        self._series: dict[str, list[np.ndarray]] = {key: [] for key in (
            "t", "pose", "vel", "closest", "largest_gap", "nearest_speed", "group_nearest",
            "social_on_robot", "social_on_agents", "social_work", "obstacle_on_robot", "obstacle_on_agents")}
        self._ped_speed_sum = 0.0
        self._ped_speed_count = 0
        self._previous_touching: np.ndarray | None = None
        self._robot_hits = 0
        self._person_hits = 0
        self._has_groups = False

    def add(self, traj: Trajectories) -> None:
        if traj.robot is None:
            return
        valid = np.isfinite(traj.robot[:, 0])
        if not valid.any():
            return
        series = self._series
        t = traj.t[valid]
        pose = traj.robot[valid]
        vel = traj.robot_vel[valid] if traj.robot_vel is not None else np.zeros((t.size, 2))
        people = traj.people[valid]
        people_vel = traj.people_vel[valid]
        series["t"].append(t)
        series["pose"].append(pose)
        series["vel"].append(vel)

        centre = np.hypot(people[:, :, 0] - pose[:, None, 0], people[:, :, 1] - pose[:, None, 1])
        gap = np.clip(centre - self.radii[None, :] - self.robot_radius, 0.0, None)
        gap = np.where(np.isfinite(gap), gap, np.inf)
        closest = gap.min(axis=1) if self.ids.size else np.full(t.size, np.inf)
        series["closest"].append(closest)
        series["largest_gap"].append(np.where(np.isfinite(gap), gap, -np.inf).max(axis=1) if self.ids.size
                                     else np.full(t.size, -np.inf))
        if self.ids.size:
            nearest = np.argmin(gap, axis=1)
            nearest_vel = people_vel[np.arange(t.size), nearest]
            series["nearest_speed"].append(np.hypot(nearest_vel[:, 0], nearest_vel[:, 1]))
            touching = gap < COLLISION_GAP
            onset = touching.copy()
            onset[1:] &= ~touching[:-1]
            if self._previous_touching is not None:
                onset[0] &= ~self._previous_touching
            self._previous_touching = touching[-1].copy()
            for f, j in zip(*np.nonzero(onset), strict=True):
                to_person = people[f, j] - pose[f, :2]
                robot_push = float(np.dot(vel[f], to_person))
                person_push = float(np.dot(people_vel[f, j], -to_person))
                if robot_push >= person_push:
                    self._robot_hits += 1
                else:
                    self._person_hits += 1
        ped_speed = np.hypot(people_vel[:, :, 0], people_vel[:, :, 1])
        finite = np.isfinite(ped_speed)
        self._ped_speed_sum += float(ped_speed[finite].sum())
        self._ped_speed_count += int(finite.sum())

        group_nearest = _group_nearest(traj, valid, self.robot_radius, self.groups)
        if group_nearest is not None:
            self._has_groups = True
            series["group_nearest"].append(group_nearest)

        forces = force_series(pose, vel, people, people_vel, self.ids, robot_radius=self.robot_radius,
                              person_radius=self.radii, walls=self.walls)
        series["social_on_robot"].append(forces.social_on_robot)
        series["social_on_agents"].append(forces.social_on_agents)
        # The three obstacle columns are computed together (with wall geometry) or not at all.
        if (forces.social_work is not None and forces.obstacle_on_robot is not None
                and forces.obstacle_on_agents is not None):
            series["social_work"].append(forces.social_work)
            series["obstacle_on_robot"].append(forces.obstacle_on_robot)
            series["obstacle_on_agents"].append(forces.obstacle_on_agents)

    def result(self) -> dict[str, float]:
        series = self._series
        if not series["t"]:
            return {}
        t = np.concatenate(series["t"])
        pose = np.concatenate(series["pose"])
        vel = np.concatenate(series["vel"])
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

        if self.goal is not None:
            gx, gy = float(self.goal[0]), float(self.goal[1])
            dist_goal = np.hypot(pose[:, 0] - gx, pose[:, 1] - gy)
            reached = np.nonzero(dist_goal - self.goal_radius < 0.3)[0]
            out["completed"] = float(reached.size > 0)
            end = reached[0] if reached.size else t.size - 1
            out["time_to_reach_goal"] = float(t[end] - t[0])
            out["minimum_distance_to_target"] = float(dist_goal.min())
            out["final_distance_to_target"] = float(dist_goal[-1])
        else:
            out["time_to_reach_goal"] = float(t[-1] - t[0])

        closest = np.concatenate(series["closest"])
        seen = np.isfinite(closest)
        if seen.any():
            out["avg_distance_to_closest_person"] = float(closest[seen].mean())
            out["minimum_distance_to_people"] = float(closest[seen].min())
            out["maximum_distance_to_people"] = float(np.concatenate(series["largest_gap"]).max())
            out.update(_space_intrusions(closest, prefix=""))
            out["avg_closest_pedestrian_velocity"] = float(np.nanmean(np.concatenate(series["nearest_speed"])))
            out["robot_on_person_collision"] = float(self._robot_hits)
            out["person_on_robot_collision"] = float(self._person_hits)
        out["avg_pedestrian_velocity"] = (self._ped_speed_sum / self._ped_speed_count
                                          if self._ped_speed_count else 0.0)
        if self._has_groups:
            nearest = np.concatenate(series["group_nearest"])
            if np.isfinite(nearest).any():
                out.update(_space_intrusions(nearest, prefix="group_"))
        with_walls = bool(series["social_work"])
        out.update(force_metrics(ForceSeries(
            social_on_robot=np.concatenate(series["social_on_robot"]),
            social_on_agents=np.concatenate(series["social_on_agents"]),
            social_work=np.concatenate(series["social_work"]) if with_walls else None,
            obstacle_on_robot=np.concatenate(series["obstacle_on_robot"]) if with_walls else None,
            obstacle_on_agents=np.concatenate(series["obstacle_on_agents"]) if with_walls else None)))
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
    nearest = _group_nearest(traj, valid, robot_radius, groups)
    if nearest is None or not np.isfinite(nearest).any():
        return {}
    return _space_intrusions(nearest, prefix="group_")


def _group_nearest(traj: Trajectories, valid: np.ndarray, robot_radius: float,
                   groups: Mapping[int, int] | None) -> np.ndarray | None:
    """Per valid robot frame, the distance to the nearest group's interaction centre (inf with no
    member present); None when there is no group at all or no valid frame."""
    if groups is None:
        membership = traj.groups
    else:
        membership = np.array([groups.get(int(agent_id), -1) for agent_id in traj.ids], dtype=np.int64)
    group_ids = np.unique(membership[membership >= 0])
    if not valid.any() or group_ids.size == 0 or traj.robot is None:
        return None
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
    return nearest


def _orient(u: np.ndarray, v: np.ndarray, w: np.ndarray) -> np.ndarray:
    return (v[..., 0] - u[..., 0]) * (w[..., 1] - u[..., 1]) - (v[..., 1] - u[..., 1]) * (w[..., 0] - u[..., 0])


def _segments_cross(p: np.ndarray, q: np.ndarray, walls: np.ndarray) -> np.ndarray:
    """For motion segments p->q (K,2) and walls (M,4): (K,) whether each motion properly crosses any wall."""
    if walls.size == 0 or p.size == 0:
        return np.zeros(p.shape[0], dtype=bool)
    a = walls[None, :, 0:2]
    b = walls[None, :, 2:4]
    p_ = p[:, None, :]
    q_ = q[:, None, :]
    d1 = _orient(a, b, p_)
    d2 = _orient(a, b, q_)
    d3 = _orient(p_, q_, a)
    d4 = _orient(p_, q_, b)
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
    """Frames x pairs where two people's bodies overlap by more than `tolerance` metres.

    A k-d tree lists the pairs within a hair more than the limit, and each one's distance is the
    same np.hypot of the same differences an all-pairs matrix holds, so the count is that of every
    pair; the matrix cost 13 ms a frame with 500 people (the app's live counters measure each frame).
    """
    from scipy.spatial import cKDTree

    count = 0
    limit = 2 * radius - tolerance
    if limit <= 0:
        return 0  # a distance is never negative
    reach = limit * (1.0 + 1e-9) + 1e-12
    for f in range(traj.frames):
        pts = traj.people[f]
        pts = pts[np.isfinite(pts[:, 0]) & np.isfinite(pts[:, 1])]
        if pts.shape[0] < 2:
            continue
        pairs = cKDTree(pts).query_pairs(reach, output_type="ndarray")
        if len(pairs) == 0:
            continue
        i, j = pairs[:, 0], pairs[:, 1]
        count += int((np.hypot(pts[i, 0] - pts[j, 0], pts[i, 1] - pts[j, 1]) < limit).sum())
    return count


WALL_CELL = 1.0  # metres: the side of the squares WallIndex buckets walls in (a step is a few centimetres)
_CELL_MARGIN = 1e-6  # metres: a wall's box is widened by this before bucketing, against rounding


class WallIndex:
    """Wall segments bucketed by the WALL_CELL squares their bounding boxes touch, so a step is tested
    only against the walls near it.

    Exact: a step whose two ends fall in one square lies inside it, a wall it properly crosses meets
    that square, and so is in its bucket; a step across squares is tested against every wall. Each
    (step, wall) test is `_orient` of the same numbers `_segments_cross` uses, so `crossings` equals
    testing every wall.
    """

    def __init__(self, walls: np.ndarray) -> None:
        self.walls = np.asarray(walls, dtype=float).reshape(-1, 4)
        cells: list[np.ndarray] = []
        owners: list[np.ndarray] = []
        for index, (x1, y1, x2, y2) in enumerate(self.walls.tolist()):
            i0 = math.floor((min(x1, x2) - _CELL_MARGIN) / WALL_CELL)
            i1 = math.floor((max(x1, x2) + _CELL_MARGIN) / WALL_CELL)
            j0 = math.floor((min(y1, y2) - _CELL_MARGIN) / WALL_CELL)
            j1 = math.floor((max(y1, y2) + _CELL_MARGIN) / WALL_CELL)
            ii, jj = np.meshgrid(np.arange(i0, i1 + 1), np.arange(j0, j1 + 1), indexing="ij")
            cells.append(np.column_stack([ii.ravel(), jj.ravel()]))
            owners.append(np.full(ii.size, index, dtype=np.int64))
        if not cells:
            self._origin, self._shape = (0, 0), (0, 0)
            self._starts = np.zeros(1, dtype=np.int64)
            self._wall_ids = np.zeros(0, dtype=np.int64)
            return
        cell = np.concatenate(cells)
        low = cell.min(axis=0)
        shape = cell.max(axis=0) - low + 1
        flat = (cell[:, 0] - low[0]) * shape[1] + (cell[:, 1] - low[1])
        order = np.argsort(flat, kind="stable")
        # CSR over a dense grid of cells: the walls of cell c are _wall_ids[_starts[c]:_starts[c + 1]].
        self._origin, self._shape = (int(low[0]), int(low[1])), (int(shape[0]), int(shape[1]))
        self._starts = np.searchsorted(flat[order], np.arange(int(shape[0] * shape[1]) + 1)).astype(np.int64)
        self._wall_ids = np.concatenate(owners)[order]

    def crossings(self, p: np.ndarray, q: np.ndarray) -> np.ndarray:
        """For motion segments p->q (K, 2): whether each properly crosses any wall."""
        out = np.zeros(p.shape[0], dtype=bool)
        if p.shape[0] == 0 or self.walls.shape[0] == 0:
            return out
        cell_p = np.floor(p / WALL_CELL).astype(np.int64)
        cell_q = np.floor(q / WALL_CELL).astype(np.int64)
        across = (cell_p != cell_q).any(axis=1)
        if across.any():
            out[across] = _segments_cross(p[across], q[across], self.walls)
        ix = cell_p[:, 0] - self._origin[0]
        iy = cell_p[:, 1] - self._origin[1]
        # A square outside the grid holds no wall: nothing to cross there.
        inside = np.flatnonzero(~across & (ix >= 0) & (iy >= 0) & (ix < self._shape[0]) & (iy < self._shape[1]))
        cell = ix[inside] * self._shape[1] + iy[inside]
        first = self._starts[cell]
        count = self._starts[cell + 1] - first
        total = int(count.sum())
        if total == 0:
            return out
        # Every (step, wall of its square) pair, flat.
        step = np.repeat(inside, count)
        wall = self._wall_ids[np.repeat(first - np.cumsum(count) + count, count) + np.arange(total)]
        a, b = self.walls[wall, 0:2], self.walls[wall, 2:4]
        p_, q_ = p[step], q[step]
        hit = (_orient(a, b, p_) * _orient(a, b, q_) < 0) & (_orient(p_, q_, a) * _orient(p_, q_, b) < 0)
        out[step[hit]] = True
        return out


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
    accumulator = CrowdAccumulator(traj.ids, walls=walls, final_goals=final_goals, goal_tolerance=goal_tolerance,
                                   events=events, walkable_area=walkable_area, radius=radius)
    accumulator.add(traj)
    return accumulator.result()


class CrowdAccumulator:
    """The crowd metrics over a run fed one chunk of consecutive frames at a time: per-agent running
    state (last position for wall crossings, closest approach to the final goal) and sums, nothing
    that grows with the run's length."""

    def __init__(self, ids: np.ndarray, *, walls: np.ndarray | None = None,
                 final_goals: Mapping[int, Sequence[float]] | None = None, goal_tolerance: float = 0.6,
                 events: Sequence[SimEvent] = (), walkable_area: float | None = None, radius: float = 0.35) -> None:
        self.ids = np.asarray(ids, dtype=np.int64)
        self.walls = None if walls is None else np.asarray(walls, dtype=float).reshape(-1, 4)
        self._wall_index = None if self.walls is None else WallIndex(self.walls)
        self.final_goals = final_goals
        self.goal_tolerance = goal_tolerance
        self.events = list(events)
        self.walkable_area = walkable_area
        self.radius = radius
        n = self.ids.size
        self._first_t: float | None = None
        self._last_t = 0.0
        self._last_point = np.full((n, 2), np.nan)
        self._crossings = np.zeros(n, dtype=np.int64)
        self._overlaps = 0
        goals = final_goals or {}
        self._goal = np.array([goals.get(int(i), (np.nan, np.nan)) for i in self.ids], dtype=float).reshape(n, 2)
        self._closest_to_goal = np.full(n, np.inf)
        self._speed_sum = 0.0
        self._speed_count = 0
        self._present_sum = 0
        self._frames = 0
        self._peak_density = 0.0

    def add(self, traj: Trajectories) -> None:
        if traj.frames == 0:
            return
        if self._first_t is None:
            self._first_t = float(traj.t[0])
        self._last_t = float(traj.t[-1])
        people = traj.people
        present = np.isfinite(people[:, :, 0])
        seen = present.any(axis=0)  # agents with a position in this chunk
        if self._wall_index is not None and seen.any():
            # Each agent's positions in order, after its last one before this chunk: steps join
            # consecutive recorded positions, across chunk boundaries too.
            sequence = np.concatenate([self._last_point[None], people], axis=0).transpose(1, 0, 2)
            recorded = np.isfinite(sequence[:, :, 0])
            owner = np.nonzero(recorded)[0]
            points = sequence[recorded]
            step = owner[:-1] == owner[1:]
            crossing = self._wall_index.crossings(points[:-1][step], points[1:][step])
            self._crossings += np.bincount(owner[:-1][step][crossing], minlength=self.ids.size)
        if seen.any():
            last_frame = traj.frames - 1 - np.argmax(present[::-1], axis=0)
            agents = np.flatnonzero(seen)
            self._last_point[agents] = people[last_frame[agents], agents]
            with np.errstate(invalid="ignore"):
                to_goal = np.hypot(people[:, :, 0] - self._goal[None, :, 0], people[:, :, 1] - self._goal[None, :, 1])
            nearest = np.where(present, to_goal, np.inf).min(axis=0)
            counted = seen & np.isfinite(self._goal[:, 0])
            self._closest_to_goal[counted] = np.minimum(self._closest_to_goal[counted], nearest[counted])
        self._overlaps += agent_overlaps(traj, radius=self.radius)
        speed = np.hypot(traj.people_vel[:, :, 0], traj.people_vel[:, :, 1])
        finite = np.isfinite(speed)
        self._speed_sum += float(speed[finite].sum())
        self._speed_count += int(finite.sum())
        self._present_sum += int(present.sum())
        self._frames += traj.frames
        self._peak_density = max(self._peak_density, _peak_local_density(traj))

    def result(self) -> dict[str, float]:
        if self._first_t is None:
            raise MetricsError("no trajectory rows")
        out: dict[str, float] = {"agents": float(self.ids.size), "duration": float(self._last_t - self._first_t)}
        if self.walls is not None:
            out["wall_penetrations"] = float(self._crossings.sum())
            out["agents_through_walls"] = float((self._crossings > 0).sum())
        out["agent_overlaps"] = float(self._overlaps)
        events = self.events
        evacuated = {e.agent_id: e.t for e in events if e.kind == "evacuated"}
        if self.final_goals:
            reached = 0
            for k, agent_id in enumerate(self.ids):
                if int(agent_id) not in self.final_goals:
                    continue
                if int(agent_id) in evacuated or self._closest_to_goal[k] <= self.goal_tolerance:
                    reached += 1
            counted = sum(1 for a in self.ids if int(a) in self.final_goals)
            out["goal_reach_rate"] = reached / counted if counted else math.nan
        if evacuated or any(e.kind == "evacuated" for e in events):
            out["evacuated"] = float(len(evacuated))
            out["evacuation_completion"] = len(evacuated) / self.ids.size if self.ids.size else math.nan
            out["evacuation_time"] = float(max(evacuated.values()) - self._first_t) if evacuated else math.nan
        out.update(queue_metrics(events))
        out["mean_speed"] = self._speed_sum / self._speed_count if self._speed_count else 0.0
        if self.walkable_area:
            out["mean_density"] = float(self._present_sum / self._frames / self.walkable_area)
        out["peak_local_density"] = self._peak_density
        return out


def _peak_local_density(traj: Trajectories, cell: float = 2.0) -> float:
    """Highest number of people per m² in any 2 m x 2 m cell at any frame (every frame counted at once:
    one integer per frame and cell)."""
    present = np.isfinite(traj.people[:, :, 0])
    if not present.any():
        return 0.0
    frame = np.nonzero(present)[0]
    keys = np.floor(traj.people[present] / cell).astype(np.int64)
    kx = keys[:, 0] - keys[:, 0].min()
    ky = keys[:, 1] - keys[:, 1].min()
    code = (frame * (int(kx.max()) + 1) + kx) * (int(ky.max()) + 1) + ky
    return int(np.unique(code, return_counts=True)[1].max()) / (cell * cell)


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
    return compute_metrics_chunks(traj.ids, [traj], walls=walls, robot_goal=robot_goal, robot_radius=robot_radius,
                                  person_radius=person_radius, final_goals=final_goals, events=events,
                                  walkable_area=walkable_area, groups=groups)


def compute_metrics_chunks(
    ids: np.ndarray,
    chunks: Iterable[Trajectories],
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
    """The metrics of a run given as consecutive chunks of whole frames on one id axis."""
    robot = RobotAccumulator(ids, robot_radius=robot_radius, person_radius=person_radius, goal=robot_goal,
                             walls=walls, groups=groups)
    crowd = CrowdAccumulator(ids, walls=walls, final_goals=final_goals, events=events,
                             walkable_area=walkable_area, radius=person_radius)
    for chunk in chunks:
        robot.add(chunk)
        crowd.add(chunk)
    return MetricsReport(robot=robot.result(), crowd=crowd.result())


class ChunkOptions(TypedDict, total=False):
    """compute_metrics_chunks' keyword arguments, as compute_metrics_csv passes them on."""

    walls: np.ndarray | None
    robot_goal: Sequence[float] | None
    robot_radius: float
    person_radius: float
    final_goals: Mapping[int, Sequence[float]] | None
    events: Sequence[SimEvent]
    walkable_area: float | None
    groups: Mapping[int, int] | None


def compute_metrics_csv(path: str | Path, *, rows_per_block: int = ROWS_PER_BLOCK,
                        **options: Unpack[ChunkOptions]) -> MetricsReport:
    """`compute_metrics` streamed over a trajectories.csv: memory is set by the block size and the
    crowd, not by the run's length (a one-hour, 500-person run reads 324 MB of CSV)."""
    ids, _groups, chunks = iter_trajectory_chunks(path, rows_per_block)
    return compute_metrics_chunks(ids, chunks, **options)
