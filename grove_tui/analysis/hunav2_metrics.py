"""HuNavSim 2.0's newer evaluator metrics: danger (fear, panic) and surprise (visibility, shock, reaction).

From robotics-upo/hunav_sim 2.0, hunav_evaluator/hunav_evaluator/hunav_metrics.py (`danger_fear_cost`,
`danger_panic_cost`, `surprise_visibility_cost`, `surprise_shock_cost`, `surprise_react_cost`), after
Singamaneni, Favier and Alami, "Towards benchmarking human-aware social robot navigation", RO-MAN 2023.
Each cost is summed over every recorded frame and every person, as the evaluator sums them; robot and
people velocities are the recorded world-frame (vx, vy).

- fear (eq. 1): |v_rel| / d when the robot closes in on the person (P_rh . v_rel > 0), with
  P_rh = person - robot and v_rel = v_robot - v_person; else 0.
- panic (eq. 2): |v_rel| / ((d_perp - R) |sin theta|) when closing in and the straight-line miss
  distance d_perp = d sin theta exceeds R = r_person + r_robot; theta is the angle between P_rh and v_rel.
- visibility (eq. 3): alpha * theta / d for a robot inside the person's 120 degree field of view and in
  line of sight on the map (Bresenham over the grid, occupied cells block), alpha = 0.45 / (pi / 3);
  theta here is the angle between the person's heading and the direction to the robot.
- shock: max(0.45 / d * (1 - gamma * SR), 0), gamma = t_react / t_recognise = 0.6 / 0.15, and
  reaction: 0.45 / d * (1 - SR), with SR = t / t_react while 0 < t < t_react else 1, t the time the
  robot has been continuously visible to that person (reset when it is not).

One deliberate difference: HuNavSim's evaluator takes the frame interval as stamp[0] - stamp[1] of the
recording (surprise_shock_cost/surprise_react_cost), which is negative for a recording in time order,
so its t never becomes positive and its shock and reaction costs are always 0. Here t accumulates the
real, positive frame interval, which is what the paper defines.

The line of sight uses the world's grid without inflation, the map HuNavSim's evaluator receives.
"""

from __future__ import annotations

import math

import numba as nb
import numpy as np

from grove_tui.analysis.metrics import Trajectories
from grove_tui.navigation.grid import OccupancyGrid

FOV_DEG = 120.0
D_PROXEMICS = 0.45
T_RECOGNISE = 0.150
T_REACT = 0.600
METRIC_NAMES = ("danger_fear_cost", "danger_panic_cost", "surprise_visibility_cost", "surprise_shock_cost",
                "surprise_react_cost")


def fear_panic(robot_pos: np.ndarray, robot_vel: np.ndarray, people: np.ndarray, people_vel: np.ndarray,
               radii: np.ndarray, robot_radius: float) -> tuple[np.ndarray, np.ndarray]:
    """Per-person fear and panic costs of one frame ((N,) each; 0 for absent people)."""
    p_rh = people - robot_pos
    v_rel = robot_vel - people_vel
    d = np.hypot(p_rh[:, 0], p_rh[:, 1])
    speed = np.hypot(v_rel[:, 0], v_rel[:, 1])
    closing = np.einsum("ij,ij->i", p_rh, v_rel)
    with np.errstate(invalid="ignore", divide="ignore"):
        fear = np.where((closing > 0) & (d > 0), speed / d, 0.0)
        cos_theta = np.clip(closing / (d * speed), -1.0, 1.0)
        sin_theta = np.abs(np.sin(np.arccos(cos_theta)))
        d_perp = d * sin_theta
        reach = radii + robot_radius
        panic = np.where((closing > 0) & (d > 0) & (speed > 0) & (d_perp > reach) & (sin_theta > 1e-6),
                         speed / ((d_perp - reach) * sin_theta), 0.0)
    return np.nan_to_num(fear), np.nan_to_num(panic)


def visibility_angle_cost(robot_pos: np.ndarray, people: np.ndarray, yaw: np.ndarray) -> np.ndarray:
    """alpha * theta / d inside the field of view, 0 outside ((N,); line of sight not checked here)."""
    to_robot = robot_pos - people
    d = np.hypot(to_robot[:, 0], to_robot[:, 1])
    with np.errstate(invalid="ignore", divide="ignore"):
        cos_theta = np.clip((np.cos(yaw) * to_robot[:, 0] + np.sin(yaw) * to_robot[:, 1]) / d, -1.0, 1.0)
        theta = np.arccos(cos_theta)
        half = math.radians(FOV_DEG) / 2.0
        alpha = D_PROXEMICS / half
        cost = np.where((d > 0) & (theta <= half), alpha * theta / d, 0.0)
    return np.nan_to_num(cost)


def line_of_sight(occupied: np.ndarray, origin: tuple[float, float], resolution: float,
                  a: tuple[float, float], b: tuple[float, float]) -> bool:
    """Bresenham from a to b over the grid (row = y, col = x); an occupied or off-map cell blocks it."""
    clear = lines_of_sight(occupied, origin, resolution, np.array([a], dtype=np.float64), b)
    return bool(clear[0])


def lines_of_sight(occupied: np.ndarray, origin: tuple[float, float], resolution: float,
                   starts: np.ndarray, b: tuple[float, float]) -> np.ndarray:
    """`line_of_sight` from each of `starts` (K, 2) to b, in compiled code: walking the cells in Python
    was most of the metrics' time in a crowd that sees the robot (the app measures every frame live)."""
    starts = np.ascontiguousarray(starts, dtype=np.float64).reshape(-1, 2)
    out = np.zeros(starts.shape[0], dtype=np.bool_)
    _lines_of_sight(np.ascontiguousarray(occupied, dtype=np.bool_), float(origin[0]), float(origin[1]),
                    float(resolution), starts, float(b[0]), float(b[1]), out)
    return out


@nb.njit(cache=True)
def _lines_of_sight(occupied: np.ndarray, ox: float, oy: float, resolution: float, starts: np.ndarray,
                    bx: float, by: float, out: np.ndarray) -> None:
    height, width = occupied.shape
    x1, y1 = int((bx - ox) / resolution), int((by - oy) / resolution)  # int(): toward zero, as Python's
    for k in range(starts.shape[0]):
        x0, y0 = int((starts[k, 0] - ox) / resolution), int((starts[k, 1] - oy) / resolution)
        dx, dy = abs(x1 - x0), abs(y1 - y0)
        sx = 1 if x0 < x1 else -1
        sy = 1 if y0 < y1 else -1
        err = dx - dy
        x, y = x0, y0
        clear = False
        while True:
            if not (0 <= x < width and 0 <= y < height) or occupied[y, x]:
                break
            if x == x1 and y == y1:
                clear = True
                break
            e2 = 2 * err
            if e2 > -dy:
                err -= dy
                x += sx
            if e2 < dx:
                err += dx
                y += sy
        out[k] = clear


def shock_react(distance: np.ndarray, visible_for: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Shock and reaction costs for people who have seen the robot for `visible_for` seconds (> 0)."""
    gamma = T_REACT / T_RECOGNISE
    sr = np.where((visible_for > 0) & (visible_for < T_REACT), visible_for / T_REACT, 1.0)
    with np.errstate(invalid="ignore", divide="ignore"):
        base = np.where(distance > 0, D_PROXEMICS / distance, 0.0)
    return np.maximum(base * (1 - gamma * sr), 0.0), base * (1 - sr)


class Hunav2Accumulator:
    """The five costs over a run read a block of frames at a time (metrics.iter_trajectory_chunks):
    what carries over between blocks is each person's time in sight of the robot and the last stamp."""

    def __init__(self, people: int, grid: OccupancyGrid, *, robot_radius: float = 0.3, person_radius: float | np.ndarray = 0.35):
        self.radii = np.broadcast_to(np.asarray(person_radius, dtype=float), (people,))
        self.robot_radius = robot_radius
        self.occupied = np.asarray(grid.occupied, dtype=bool)
        self.origin = (float(grid.origin[0]), float(grid.origin[1]))
        self.resolution = float(grid.resolution)
        self.totals = dict.fromkeys(METRIC_NAMES, 0.0)
        self.visible_for = np.zeros(people)
        self.previous_t: float | None = None
        self.saw_robot = False

    def add(self, traj: Trajectories) -> None:
        if traj.robot is None or traj.robot_vel is None:
            self.visible_for[:] = 0.0
            if traj.frames:
                self.previous_t = float(traj.t[-1])
            return
        self.saw_robot = True
        for f in range(traj.frames):
            self._frame(traj, f)

    def _frame(self, traj: Trajectories, f: int) -> None:
        assert traj.robot is not None and traj.robot_vel is not None  # add() steps only runs with a robot
        dt = 0.0 if self.previous_t is None else max(float(traj.t[f]) - self.previous_t, 0.0)
        self.previous_t = float(traj.t[f])
        robot = traj.robot[f]
        if not np.all(np.isfinite(robot[:2])):
            self.visible_for[:] = 0.0
            return
        present = np.isfinite(traj.people[f, :, 0])
        people = np.where(present[:, None], traj.people[f], 0.0)
        robot_pos = robot[:2]
        fear, panic = fear_panic(robot_pos, np.nan_to_num(traj.robot_vel[f]), people,
                                 np.nan_to_num(traj.people_vel[f]), self.radii, self.robot_radius)
        angle_cost = visibility_angle_cost(robot_pos, people, np.nan_to_num(traj.people_yaw[f]))
        seen = present & (angle_cost > 0)
        looking = np.flatnonzero(seen)
        if looking.size:
            clear = lines_of_sight(self.occupied, self.origin, self.resolution, people[looking],
                                   (robot_pos[0], robot_pos[1]))
            seen[looking[~clear]] = False
        self.visible_for = np.where(seen, self.visible_for + dt, 0.0)
        shock, react = shock_react(np.hypot(*(robot_pos - people).T), self.visible_for)
        self.totals["danger_fear_cost"] += float(fear[present].sum())
        self.totals["danger_panic_cost"] += float(panic[present].sum())
        self.totals["surprise_visibility_cost"] += float(angle_cost[seen].sum())
        self.totals["surprise_shock_cost"] += float(shock[seen].sum())
        self.totals["surprise_react_cost"] += float(react[seen].sum())

    def result(self) -> dict[str, float]:
        """The totals ({} for a run without a robot, as the evaluator has nothing to measure)."""
        return dict(self.totals) if self.saw_robot else {}


def hunav2_costs(traj: Trajectories, grid: OccupancyGrid, *, robot_radius: float = 0.3,
                 person_radius: float | np.ndarray = 0.35) -> dict[str, float]:
    """The five HuNavSim 2.0 costs of a run held in memory (empty without a robot)."""
    accumulator = Hunav2Accumulator(traj.ids.size, grid, robot_radius=robot_radius, person_radius=person_radius)
    accumulator.add(traj)
    return accumulator.result()
