"""The pedestrian crowd: structure-of-arrays state, per-agent intents, a robot, and the SFM step.

Behaviours change intents (goals, mode, speed, factors, face target) between steps through the
methods below; `step(n)` then runs n steps in one compiled call with no Python per agent.
Agent rows are 0-based indices; mapping them to scenario ids is the caller's business.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Callable, Iterable, Sequence
from typing import TYPE_CHECKING, Any

import numba
import numpy as np

from grove_tui.crowd import sfm
from grove_tui.errors import CrowdError
if TYPE_CHECKING:
    from grove_tui.navigation.grid import OccupancyGrid
    from grove_tui.navigation.velocity_field import VelocityField
from grove_tui.crowd.sfm import (
    FACE_AGENT,
    FACE_POINT,
    FACE_ROBOT,
    MODE_FACE,
    MODE_FIELD,
    MODE_GOALS,
    MODE_STOP,
    ROBOT_AS_AGENT,
    ROBOT_AS_OBSTACLE,
    ROBOT_FEARED,
    ROBOT_IGNORED,
    SFMParams,
)

__all__ = [
    "Crowd",
    "CrowdError",
    "SFMParams",
    "MODE_GOALS",
    "MODE_FIELD",
    "MODE_STOP",
    "MODE_FACE",
    "ROBOT_AS_AGENT",
    "ROBOT_AS_OBSTACLE",
    "ROBOT_IGNORED",
    "ROBOT_FEARED",
]

_MODES = (MODE_GOALS, MODE_FIELD, MODE_STOP, MODE_FACE)
_ROBOT_INTERACTIONS = (ROBOT_AS_AGENT, ROBOT_AS_OBSTACLE, ROBOT_IGNORED, ROBOT_FEARED)
_FACTOR_NAMES = ("goal", "obstacle", "social", "other")


def _point(value: object, what: str) -> tuple[float, float]:
    """`value` as a finite (x, y) pair; it is whatever the caller was handed, checked here."""
    if not isinstance(value, Iterable):
        raise CrowdError(f"{what} must be an (x, y) pair of numbers, got {value!r}")
    try:
        x, y = (float(v) for v in value)
    except (TypeError, ValueError) as exc:
        raise CrowdError(f"{what} must be an (x, y) pair of numbers, got {value!r}") from exc
    if not (math.isfinite(x) and math.isfinite(y)):
        raise CrowdError(f"{what} must be finite, got ({x}, {y})")
    return x, y


class Crowd:
    """SFM pedestrians plus one optional robot, stepped at a fixed dt."""

    # Below this many agents a step is too short to pay for waking threads; both paths give equal
    # results. Measured on 2 shared cores (bench/sfm.py's room, load 8): serial 1.71M agent-steps per
    # CPU-second and 0.78M per wall second at 1,000 agents against 1.43M and 0.49M on two threads;
    # at 4,000 the threads win on the wall clock (0.83M against 0.60M) for 4% more CPU.
    parallel_threshold = 4000

    def __init__(self, walls: np.ndarray | Sequence[Sequence[float]] | None = None,
                 params: SFMParams | None = None, dt: float = 0.05, seed: int = 0,
                 grid: OccupancyGrid | None = None, periodic_x: tuple[float, float] | None = None,
                 precision: str = "float64") -> None:
        """`periodic_x` = (x0, x1): x wraps from x1 back to x0 and people interact across that seam,
        as in a corridor with no ends (the fundamental diagram is measured in one). Walls along the
        corridor should reach a little past both ends; a periodic crowd always steps on one thread.
        `precision` "float32" computes the pairwise terms in single precision (positions, velocities and
        every sum stay float64): faster, and within SINGLE_PRECISION_TOLERANCE of "float64" (tests/crowd)."""
        if dt <= 0 or not math.isfinite(dt):
            raise CrowdError(f"Crowd dt must be a positive number of seconds, got {dt!r}")
        wall_array = np.zeros((0, 4)) if walls is None else np.asarray(walls, dtype=np.float64)
        if wall_array.size == 0:
            wall_array = np.zeros((0, 4), dtype=np.float64)
        if wall_array.ndim != 2 or wall_array.shape[1] != 4:
            raise CrowdError(f"Crowd walls must be an (M, 4) array of x1, y1, x2, y2, got shape {wall_array.shape}")
        if not np.all(np.isfinite(wall_array)):
            raise CrowdError("Crowd walls contain NaN or infinite coordinates")
        if precision not in ("float64", "float32"):
            raise CrowdError(f"Crowd precision must be 'float64' or 'float32', got {precision!r}")
        self.precision = precision
        self._precision = np.empty(0, dtype=np.float32 if precision == "float32" else np.float64)
        self.params = params if params is not None else SFMParams()
        self.dt = float(dt)
        self.seed = int(seed)
        # Seeded for callers (spawn jitter etc.); the physics itself draws no random numbers.
        self.rng = np.random.default_rng(self.seed)
        self.grid = grid
        self.walls = np.ascontiguousarray(wall_array)
        self._params_array = self.params.as_array()
        if periodic_x is not None:
            x0, x1 = (float(v) for v in periodic_x)
            # The pair search looks `cutoff` ahead across the seam: a shorter period would meet
            # the same neighbour twice.
            if not (math.isfinite(x0) and math.isfinite(x1) and x1 - x0 >= 3.0 * self.params.cutoff):
                raise CrowdError(f"periodic_x must span at least 3 x the {self.params.cutoff:g} m cutoff, "
                                 f"got {periodic_x!r}")
            self._params_array[sfm.P_PERIOD] = x1 - x0
            self._params_array[sfm.P_PERIOD_X0] = x0
        self.periodic_x = periodic_x
        self._wall_owner = sfm.wall_endpoint_owners(self.walls)
        bucket_cell = self.params.wall_range + 0.5
        self._wall_meta, self._wall_start, self._wall_items = sfm.bucket_walls(self.walls, bucket_cell)
        self._free_meta, self._wall_free = sfm.wall_distance_field(self.walls, self.params.wall_range + 1.0)
        self.time = 0.0
        self.step_count = 0
        self.n = 0
        self._allocate(16, 4)
        self._robot = np.zeros(sfm.R_COUNT, dtype=np.float64)
        self._robot_path = np.zeros((0, 2), dtype=np.float64)
        self._fields: list[VelocityField] = []
        self._field_vectors = np.zeros((1, 1, 1, 2), dtype=np.float32)
        self._field_meta = np.zeros((1, sfm.F_COUNT), dtype=np.float64)
        self._field_meta[0, sfm.F_RES] = 1.0
        self._field_meta[0, sfm.F_H] = 1.0
        self._field_meta[0, sfm.F_W] = 1.0
        self._group_cache = np.zeros(0, dtype=np.int32)
        self._group_slot = np.zeros(0, dtype=np.int32)
        self._group_start = np.zeros(1, dtype=np.int32)
        self._group_members = np.zeros(0, dtype=np.int32)

    # ------------------------------------------------------------------ storage

    def _allocate(self, capacity: int, goal_capacity: int) -> None:
        self._cap = capacity
        self._pos = np.zeros((capacity, 2))
        self._vel = np.zeros((capacity, 2))
        self._yaw = np.zeros(capacity)
        self._radius = np.zeros(capacity)
        self._desired_speed = np.zeros(capacity)
        self._base_speed = np.zeros(capacity)
        self._group = np.full(capacity, -1, dtype=np.int32)
        self._factors = np.zeros((capacity, 4))
        self._base_factors = np.zeros((capacity, 4))
        self._mode = np.zeros(capacity, dtype=np.int8)
        self._active = np.zeros(capacity, dtype=np.bool_)
        self._goals = np.zeros((capacity, goal_capacity, 2))
        self._goal_len = np.zeros(capacity, dtype=np.int32)
        self._goal_front = np.zeros(capacity, dtype=np.int32)
        self._goal_radius = np.zeros(capacity)
        self._cyclic = np.zeros(capacity, dtype=np.bool_)
        self._field_slot = np.full(capacity, -1, dtype=np.int32)
        self._face_kind = np.zeros(capacity, dtype=np.int8)
        self._face_ref = np.full(capacity, -1, dtype=np.int32)
        self._face_point = np.zeros((capacity, 2))
        self._robot_interaction = np.zeros(capacity, dtype=np.int8)
        # Where a standing agent stopped (NaN while it walks); the kernel sets and clears it.
        self._anchor = np.full((capacity, 2), np.nan)
        # The narrowest gap to any other body at the start of the last step (the kernel's pair pass).
        self._min_gap = np.full(capacity, np.inf)

    _PER_AGENT = ("_pos", "_vel", "_yaw", "_radius", "_desired_speed", "_base_speed", "_group", "_factors",
                  "_base_factors", "_mode", "_active", "_goal_len", "_goal_front", "_goal_radius", "_cyclic",
                  "_field_slot", "_face_kind", "_face_ref", "_face_point", "_robot_interaction", "_anchor",
                  "_min_gap")

    def _grow(self, capacity: int) -> None:
        old = {name: getattr(self, name) for name in self._PER_AGENT}
        old_goals = self._goals
        self._allocate(capacity, old_goals.shape[1])
        for name, array in old.items():
            getattr(self, name)[: self.n] = array[: self.n]
        self._goals[: self.n] = old_goals[: self.n]

    def _grow_goals(self, goal_capacity: int) -> None:
        goals = np.zeros((self._cap, goal_capacity, 2))
        goals[:, : self._goals.shape[1]] = self._goals
        self._goals = goals

    # ------------------------------------------------------------------ public arrays (views of the live rows)

    @property
    def pos(self) -> np.ndarray:
        return self._pos[: self.n]

    @property
    def vel(self) -> np.ndarray:
        return self._vel[: self.n]

    @property
    def yaw(self) -> np.ndarray:
        return self._yaw[: self.n]

    @property
    def radius(self) -> np.ndarray:
        return self._radius[: self.n]

    @property
    def desired_speed(self) -> np.ndarray:
        return self._desired_speed[: self.n]

    @property
    def group(self) -> np.ndarray:
        return self._group[: self.n]

    @property
    def factors(self) -> np.ndarray:
        return self._factors[: self.n]

    @property
    def mode(self) -> np.ndarray:
        return self._mode[: self.n]

    @property
    def active(self) -> np.ndarray:
        return self._active[: self.n]

    @property
    def min_gap(self) -> np.ndarray:
        """Per agent, the narrowest gap (m) between its body and any other within the cutoff at the start
        of the last step (negative: overlapping; a lower bound when nobody is that near; inf if inactive).
        Contact counters use it to look only at people who may touch."""
        return self._min_gap[: self.n]

    @property
    def goal_radius(self) -> np.ndarray:
        return self._goal_radius[: self.n]

    @property
    def robot_interaction(self) -> np.ndarray:
        return self._robot_interaction[: self.n]

    # ------------------------------------------------------------------ agents

    def _check(self, i: int) -> int:
        if isinstance(i, (bool, np.bool_)) or not isinstance(i, (int, np.integer)):
            raise CrowdError(f"agent index must be an int, got {i!r}")
        if not 0 <= int(i) < self.n:
            raise CrowdError(f"agent index {i} out of range: the crowd has {self.n} agents (0..{self.n - 1})")
        return int(i)

    def add_agent(self, position: Sequence[float], *, radius: float = 0.35, desired_speed: float = 1.0,
                  group: int = -1, goals: Iterable[Sequence[float]] = (), goal_radius: float = 0.3,
                  cyclic: bool = False, factors: Sequence[float] | None = None, yaw: float = 0.0,
                  robot_interaction: int = ROBOT_AS_AGENT) -> int:
        """Add a pedestrian and return its row index. A spawn inside an obstacle moves to free space."""
        x, y = _point(position, "agent position")
        if not radius > 0:
            raise CrowdError(f"agent radius must be > 0, got {radius!r}")
        if not desired_speed >= 0:
            raise CrowdError(f"agent desired_speed must be >= 0, got {desired_speed!r}")
        factor_values = self.params.factors() if factors is None else tuple(float(f) for f in factors)
        if len(factor_values) != 4:
            raise CrowdError(f"agent factors must be (goal, obstacle, social, other), got {factors!r}")
        if robot_interaction not in _ROBOT_INTERACTIONS:
            raise CrowdError(f"unknown robot_interaction {robot_interaction!r}")
        x, y = self._free_spawn(x, y, float(radius))
        if self.n == self._cap:
            self._grow(self._cap * 2)
        i = self.n
        self.n += 1
        self._pos[i] = (x, y)
        self._vel[i] = 0.0
        self._yaw[i] = float(yaw)
        self._radius[i] = float(radius)
        self._desired_speed[i] = float(desired_speed)
        self._base_speed[i] = float(desired_speed)
        self._group[i] = int(group)
        self._factors[i] = factor_values
        self._base_factors[i] = factor_values
        self._mode[i] = MODE_GOALS
        self._active[i] = True
        self._goal_len[i] = 0
        self._goal_front[i] = 0
        self._goal_radius[i] = float(goal_radius)
        self._cyclic[i] = bool(cyclic)
        self._field_slot[i] = -1
        self._face_kind[i] = FACE_POINT
        self._face_ref[i] = -1
        self._face_point[i] = (x, y)
        self._robot_interaction[i] = robot_interaction
        self._anchor[i] = np.nan
        goal_list = list(goals)
        if goal_list:
            self.set_goals(i, goal_list)
        return i

    def _free_spawn(self, x: float, y: float, radius: float) -> tuple[float, float]:
        if self.grid is not None:
            if not self.grid.is_free(x, y):
                free = self.grid.nearest_free(x, y)
                if free is None:
                    raise CrowdError(f"agent spawn ({x:.2f}, {y:.2f}) is inside an obstacle and no free cell exists")
                warnings.warn(f"agent spawn ({x:.2f}, {y:.2f}) is inside an obstacle; moved to "
                              f"({free[0]:.2f}, {free[1]:.2f})", stacklevel=3)
                x, y = float(free[0]), float(free[1])
            return x, y
        if self.walls.shape[0] == 0:
            return x, y
        clearance = self.params.wall_clearance * radius
        nx, ny, _vx, _vy = sfm.resolve_motion(x, y, x, y, 0.0, 0.0, clearance, self.walls,
                                              self._wall_meta, self._wall_start, self._wall_items)
        if (nx, ny) != (x, y):
            warnings.warn(f"agent spawn ({x:.2f}, {y:.2f}) is within {clearance:.2f} m of a wall; moved to "
                          f"({nx:.2f}, {ny:.2f})", stacklevel=3)
        return float(nx), float(ny)

    def set_active(self, i: int, active: bool) -> None:
        """Inactive (evacuated, removed) agents neither move nor take part in anyone's forces."""
        i = self._check(i)
        self._active[i] = bool(active)
        if not active:
            self._vel[i] = 0.0

    def set_group(self, i: int, group: int) -> None:
        self._group[self._check(i)] = int(group)

    def set_robot_interaction(self, i: int, interaction: int) -> None:
        """ROBOT_AS_AGENT (Regular), ROBOT_AS_OBSTACLE (Impassive), ROBOT_IGNORED, ROBOT_FEARED (Scared)."""
        i = self._check(i)
        if interaction not in _ROBOT_INTERACTIONS:
            raise CrowdError(f"unknown robot interaction {interaction!r}; use one of {_ROBOT_INTERACTIONS}")
        self._robot_interaction[i] = interaction

    # ------------------------------------------------------------------ goals

    def set_goals(self, i: int, points: Iterable[Sequence[float]], goal_radius: float | None = None,
                  cyclic: bool | None = None) -> None:
        """Replace agent i's goal list (front first). An empty list clears it."""
        i = self._check(i)
        pts = [_point(p, f"goal of agent {i}") for p in points]
        if len(pts) > self._goals.shape[1]:
            self._grow_goals(max(len(pts), 2 * self._goals.shape[1]))
        if pts:
            self._goals[i, : len(pts)] = pts
        self._goal_len[i] = len(pts)
        self._goal_front[i] = 0
        self._anchor[i] = np.nan  # a new intent: the next place it stands is its spot
        if goal_radius is not None:
            if not goal_radius >= 0:
                raise CrowdError(f"goal_radius must be >= 0, got {goal_radius!r}")
            self._goal_radius[i] = float(goal_radius)
        if cyclic is not None:
            self._cyclic[i] = bool(cyclic)

    def append_goal(self, i: int, point: Sequence[float]) -> None:
        """HuNavSim SetGoal: append one goal at the back of the list."""
        i = self._check(i)
        self.set_goals(i, [*self.goals(i), _point(point, f"goal of agent {i}")])

    def goals(self, i: int) -> list[tuple[float, float]]:
        """The remaining goals of agent i, front first (for cyclic lists: all, from the front)."""
        i = self._check(i)
        length = int(self._goal_len[i])
        front = int(self._goal_front[i])
        if self._cyclic[i]:
            indices = [(front + k) % length for k in range(length)] if length else []
        else:
            indices = list(range(front, length))
        return [(float(self._goals[i, k, 0]), float(self._goals[i, k, 1])) for k in indices]

    def current_goal(self, i: int) -> tuple[float, float] | None:
        i = self._check(i)
        front = int(self._goal_front[i])
        if front >= self._goal_len[i]:
            return None
        return float(self._goals[i, front, 0]), float(self._goals[i, front, 1])

    def goals_left(self, i: int) -> int:
        i = self._check(i)
        return int(self._goal_len[i] - self._goal_front[i]) if not self._cyclic[i] else int(self._goal_len[i])

    def goal_reached(self, i: int) -> bool:
        """HuNavSim IsGoalReached: within goal radius + tolerance of the front goal.

        In MODE_FIELD the front goal is the field's exit. With no goal at all there is nothing
        left to reach, so this is True.
        """
        i = self._check(i)
        if self._mode[i] == MODE_FIELD and self._field_slot[i] >= 0:
            meta = self._field_meta[self._field_slot[i]]
            target: tuple[float, float] | None = (float(meta[sfm.F_EXIT_X]), float(meta[sfm.F_EXIT_Y]))
        else:
            target = self.current_goal(i)
        if target is None:
            return True
        dx = target[0] - self._pos[i, 0]
        dy = target[1] - self._pos[i, 1]
        return math.hypot(dx, dy) <= self._goal_radius[i] + self.params.goal_tolerance

    def advance_goal(self, i: int) -> None:
        """HuNavSim UpdateGoal: pop the front goal, re-appending it at the back when cyclic."""
        i = self._check(i)
        length = int(self._goal_len[i])
        if length == 0:
            return
        if self._cyclic[i]:
            self._goal_front[i] = (self._goal_front[i] + 1) % length
        elif self._goal_front[i] < length:
            self._goal_front[i] += 1

    # ------------------------------------------------------------------ modes and behaviour knobs

    def set_mode(self, i: int, mode: int) -> None:
        i = self._check(i)
        if mode not in _MODES:
            raise CrowdError(f"unknown mode {mode!r}; use MODE_GOALS, MODE_FIELD, MODE_STOP or MODE_FACE")
        if mode == MODE_FIELD and self._field_slot[i] < 0:
            raise CrowdError(f"agent {i} has no velocity field; call set_field(i, field_id) first")
        if mode != self._mode[i]:
            self._anchor[i] = np.nan
        self._mode[i] = mode

    def register_field(self, field: VelocityField) -> int:
        """Register a VelocityField (origin, resolution, vectors (H, W, 2), exit); returns its id."""
        vectors = np.asarray(field.vectors, dtype=np.float32)
        if vectors.ndim != 3 or vectors.shape[2] != 2:
            raise CrowdError(f"velocity field vectors must have shape (H, W, 2), got {vectors.shape}")
        resolution = float(field.resolution)
        if not resolution > 0:
            raise CrowdError(f"velocity field resolution must be > 0, got {resolution!r}")
        ox, oy = _point(field.origin, "velocity field origin")
        exit_point = getattr(field, "exit", None)
        # Without an exit the kernel's "arrived" test must never fire: put it out of reach.
        ex, ey = _point(exit_point, "velocity field exit") if exit_point is not None else (1e30, 1e30)
        self._fields.append(field)
        count = len(self._fields)
        height = max(self._field_vectors.shape[1], vectors.shape[0])
        width = max(self._field_vectors.shape[2], vectors.shape[1])
        stacked = np.zeros((count, height, width, 2), dtype=np.float32)
        meta = np.zeros((count, sfm.F_COUNT), dtype=np.float64)
        if count > 1:
            old = self._field_vectors
            stacked[: count - 1, : old.shape[1], : old.shape[2]] = old
            meta[: count - 1] = self._field_meta[: count - 1]
        stacked[count - 1, : vectors.shape[0], : vectors.shape[1]] = vectors
        meta[count - 1] = (ox, oy, resolution, vectors.shape[0], vectors.shape[1], ex, ey)
        self._field_vectors = stacked
        self._field_meta = meta
        return count - 1

    def set_field(self, i: int, field_id: int) -> None:
        """Give agent i a registered field; it follows it once in MODE_FIELD."""
        i = self._check(i)
        if not 0 <= int(field_id) < len(self._fields):
            raise CrowdError(f"unknown field id {field_id}; {len(self._fields)} fields are registered")
        self._field_slot[i] = int(field_id)

    def set_face_target(self, i: int, target: Sequence[float] | int | str) -> None:
        """What agent i turns to in MODE_FACE: an (x, y) point, another agent's index, or "robot"."""
        i = self._check(i)
        if isinstance(target, str):
            if target != "robot":
                raise CrowdError(f"face target must be a point, an agent index or 'robot', got {target!r}")
            self._face_kind[i] = FACE_ROBOT
        elif isinstance(target, (int, np.integer)) and not isinstance(target, (bool, np.bool_)):
            self._face_ref[i] = self._check(int(target))
            self._face_kind[i] = FACE_AGENT
        else:
            self._face_point[i] = _point(target, f"face target of agent {i}")
            self._face_kind[i] = FACE_POINT

    def set_speed(self, i: int, v: float) -> None:
        i = self._check(i)
        if not (v >= 0 and math.isfinite(v)):
            raise CrowdError(f"speed of agent {i} must be a finite number >= 0, got {v!r}")
        self._desired_speed[i] = float(v)

    def restore_speed(self, i: int) -> None:
        i = self._check(i)
        self._desired_speed[i] = self._base_speed[i]

    def set_factors(self, i: int, goal: float | None = None, obstacle: float | None = None,
                    social: float | None = None, other: float | None = None) -> None:
        i = self._check(i)
        for k, value in enumerate((goal, obstacle, social, other)):
            if value is not None:
                if not math.isfinite(value):
                    raise CrowdError(f"{_FACTOR_NAMES[k]} factor of agent {i} must be finite, got {value!r}")
                self._factors[i, k] = float(value)

    def restore_factors(self, i: int) -> None:
        i = self._check(i)
        self._factors[i] = self._base_factors[i]

    # ------------------------------------------------------------------ robot

    def set_robot(self, position: Sequence[float], *, radius: float = 0.3, max_speed: float = 0.8,
                  path: np.ndarray | Sequence[Sequence[float]] | None = None, yaw: float = 0.0) -> None:
        x, y = _point(position, "robot position")
        if not radius > 0 or not max_speed >= 0:
            raise CrowdError(f"robot radius must be > 0 and max_speed >= 0, got {radius!r}, {max_speed!r}")
        self._robot[:] = 0.0
        self._robot[sfm.R_X] = x
        self._robot[sfm.R_Y] = y
        self._robot[sfm.R_YAW] = float(yaw)
        self._robot[sfm.R_RADIUS] = float(radius)
        self._robot[sfm.R_MAX_SPEED] = float(max_speed)
        self._robot[sfm.R_PRESENT] = 1.0
        self.set_robot_path(path)

    def set_robot_path(self, path: np.ndarray | Sequence[Sequence[float]] | None) -> None:
        """Scripted (K, 2) path the robot follows at max speed; None or empty means stand still."""
        if path is None:
            arr = np.zeros((0, 2), dtype=np.float64)
        else:
            arr = np.ascontiguousarray(path, dtype=np.float64).reshape(-1, 2)
            if not np.all(np.isfinite(arr)):
                raise CrowdError("robot path contains NaN or infinite points")
        self._robot_path = arr
        self._robot[sfm.R_PATH_INDEX] = 0.0

    def command_robot(self, vx: float, vy: float) -> None:
        """Velocity command (clipped to max speed); overrides the path until clear_robot_command()."""
        if not self.has_robot:
            raise CrowdError("command_robot: no robot; call set_robot first")
        if not (math.isfinite(vx) and math.isfinite(vy)):
            raise CrowdError(f"robot command must be finite, got ({vx!r}, {vy!r})")
        self._robot[sfm.R_COMMANDED] = 1.0
        self._robot[sfm.R_CMD_VX] = float(vx)
        self._robot[sfm.R_CMD_VY] = float(vy)

    def clear_robot_command(self) -> None:
        self._robot[sfm.R_COMMANDED] = 0.0
        self._robot[sfm.R_CMD_VX] = 0.0
        self._robot[sfm.R_CMD_VY] = 0.0

    @property
    def robot_commanded(self) -> bool:
        """A velocity command drives the robot (a user, a policy), not its scripted path."""
        return bool(self._robot[sfm.R_COMMANDED])

    def set_robot_speed_limit(self, speed: float) -> None:
        """The most the robot may drive at (a scripted robot slows or stops for someone in its way)."""
        if not (math.isfinite(speed) and speed >= 0):
            raise CrowdError(f"robot speed limit must be >= 0, got {speed!r}")
        self._robot[sfm.R_MAX_SPEED] = float(speed)

    @property
    def robot_speed_limit(self) -> float:
        return float(self._robot[sfm.R_MAX_SPEED])

    @property
    def has_robot(self) -> bool:
        return bool(self._robot[sfm.R_PRESENT])

    @property
    def robot_pos(self) -> np.ndarray | None:
        return self._robot[sfm.R_X: sfm.R_Y + 1].copy() if self.has_robot else None

    @property
    def robot_vel(self) -> np.ndarray | None:
        return self._robot[sfm.R_VX: sfm.R_VY + 1].copy() if self.has_robot else None

    @property
    def robot_yaw(self) -> float | None:
        return float(self._robot[sfm.R_YAW]) if self.has_robot else None

    @property
    def robot_radius(self) -> float | None:
        return float(self._robot[sfm.R_RADIUS]) if self.has_robot else None

    @property
    def robot_path_done(self) -> bool:
        """True once the robot stands at the last point of its scripted path."""
        if not self.has_robot or self._robot_path.shape[0] == 0:
            return True
        last = self._robot_path[-1]
        at_last = int(self._robot[sfm.R_PATH_INDEX]) == self._robot_path.shape[0] - 1
        return at_last and math.hypot(last[0] - self._robot[sfm.R_X], last[1] - self._robot[sfm.R_Y]) <= 0.05

    # ------------------------------------------------------------------ stepping

    def _refresh_groups(self) -> None:
        groups = self._group[: self.n]
        if np.array_equal(groups, self._group_cache):
            return
        self._group_cache = groups.copy()
        slot = np.full(self.n, -1, dtype=np.int32)
        members = np.flatnonzero(groups >= 0)
        ids, inverse = np.unique(groups[members], return_inverse=True)
        slot[members] = inverse.astype(np.int32)
        order = members[np.argsort(inverse, kind="stable")].astype(np.int32)
        counts = np.bincount(inverse, minlength=len(ids)) if len(ids) else np.zeros(0, dtype=np.int64)
        start = np.zeros(len(ids) + 1, dtype=np.int32)
        np.cumsum(counts, out=start[1:])
        self._group_slot = slot
        self._group_start = start
        self._group_members = order

    def step(self, n: int = 1) -> None:
        """Advance the crowd and the robot by n fixed steps of dt."""
        n = int(n)
        if n <= 0:
            return
        self._refresh_groups()
        self._check_finite()
        k = self.n
        if k >= self.parallel_threshold and self.periodic_x is None:
            # Work handed out one block (or band) at a time: when another process holds one core,
            # the thread that runs takes more blocks instead of waiting for its static half.
            with numba.parallel_chunksize(1):
                self._advance(sfm.advance_parallel, n)
        else:
            self._advance(sfm.advance_serial, n)
        self.step_count += n
        self.time = self.step_count * self.dt

    def profile(self, n: int = 1) -> dict[str, float]:
        """Advance n steps like step(n) on one thread, timing each pass: {phase: CPU seconds}
        (sfm.PROFILE_PHASES). For benchmarks: the passes are called from Python one by one."""
        n = int(n)
        spent = dict.fromkeys(sfm.PROFILE_PHASES, 0.0)
        if n <= 0:
            return spent
        self._refresh_groups()
        self._check_finite()
        spent = self._advance(sfm.profile_steps, n)
        self.step_count += n
        self.time = self.step_count * self.dt
        return spent

    def _check_finite(self) -> None:
        k = self.n
        state = np.concatenate([self._pos[:k], self._vel[:k]], axis=1)
        if not np.isfinite(state).all():
            # Values written into pos/vel from outside; the kernel's cell indexing needs finite input.
            bad = np.flatnonzero(~np.isfinite(state).all(axis=1))
            raise CrowdError(f"agents {bad[:10].tolist()} have a non-finite position or velocity")

    def _advance(self, kernel: Callable[..., Any], n: int) -> Any:  # Any: a numba kernel (no stubs), returning what that kernel returns
        k = self.n
        return kernel(
            n, self.dt, self._params_array,
            self._pos[:k], self._vel[:k], self._yaw[:k], self._radius[:k], self._desired_speed[:k],
            self._factors[:k], self._mode[:k], self._active[:k],
            self._group_slot, self._group_start, self._group_members,
            self._goals[:k], self._goal_len[:k], self._goal_front[:k], self._goal_radius[:k], self._cyclic[:k],
            self._field_slot[:k], self._field_vectors, self._field_meta,
            self._face_kind[:k], self._face_ref[:k], self._face_point[:k], self._anchor[:k],
            self._robot_interaction[:k], self._robot, self._robot_path,
            self.walls, self._wall_owner, self._wall_meta, self._wall_start, self._wall_items,
            self._free_meta, self._wall_free, _block_size(k), self._min_gap[:k], self._precision,
        )


def _block_size(n: int) -> int:
    """Agents per parallel work item: about four items per thread (so a thread that lost its core
    to another process hands over work), never so few agents that scheduling costs more than them."""
    return max(64, -(-n // (4 * max(numba.get_num_threads(), 1))))
