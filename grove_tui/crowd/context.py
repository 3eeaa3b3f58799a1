"""What leaves see of the simulation: the crowd (through its intents only), time, world geometry,
the shared coordination objects, and per-agent bookkeeping (status text, counters).

Leaves never move agents themselves: they set intents on the crowd (goals, mode, field, face target,
speed, force factors, active) between steps, and the numba step does the rest.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np

from grove_tui.bt.runtime.tree_node import SimClock
from grove_tui.crowd.coordination import ConversationRegistry, QueueRegistry, SpeechLog
from grove_tui.crowd.crowd import Crowd
from grove_tui.navigation.grid import OccupancyGrid
from grove_tui.navigation.theta_star import ThetaStarPlanner
from grove_tui.world.model import World
from grove_tui.errors import BTError

Point = tuple[float, float]
# The intents a temporary behavior replaces and gives back (SimContext.snapshot): goals, SFM mode,
# desired speed, force factors, robot interaction.
Snapshot = tuple[list[Point], int, float, tuple[float, ...], int]


class Counters:
    """Running totals the TUI shows and evaluation reads."""

    __slots__ = ("reached_goals", "served", "evacuated", "collisions", "robot_collisions", "closest_robot_approach",
                 "finished_trees")

    def __init__(self) -> None:
        self.reached_goals = 0
        self.served = 0
        self.evacuated = 0
        self.collisions = 0  # new agent-agent contacts (bodies overlapping)
        self.robot_collisions = 0  # new agent-robot contacts (gap < 0.02 m, HuNavSim's threshold)
        self.closest_robot_approach = math.inf  # smallest gap between the robot and any agent (m)
        self.finished_trees = 0


class SimContext:
    """Shared by every leaf of every agent in one simulation."""

    def __init__(self, crowd: Crowd, clock: SimClock, *, ids: Sequence[int], seed: int = 0, world: World | None = None,
                 grid: OccupancyGrid | None = None, planner: ThetaStarPlanner | None = None,
                 walls: np.ndarray | None = None,
                 fields: dict[str, int] | None = None, goal_table: dict[int, Point] | None = None,
                 groups: dict[int, tuple[int, ...]] | None = None, base_speed: Sequence[float] | None = None):
        self.crowd = crowd
        self.clock = clock
        self.rng = np.random.default_rng([int(seed) & 0xFFFFFFFF, 0xB7E15162])
        self.world = world
        self.grid = grid
        self.planner = planner
        self.walls = np.zeros((0, 4)) if walls is None else np.asarray(walls, dtype=np.float64)
        self.fields = dict(fields or {})  # scenario field id -> crowd field slot
        self.field_exits: dict[str, Point] = {}
        self.goal_table = dict(goal_table or {})  # HuNavSim global goal id -> point
        self.ids = list(ids)  # row -> agent id
        self.row_of = {agent_id: row for row, agent_id in enumerate(self.ids)}
        self.groups = dict(groups or {})  # agent id -> ids of its draft group (itself included)
        self.base_speed = list(base_speed) if base_speed is not None else [1.0] * len(self.ids)
        self.queues = QueueRegistry(self)
        self.conversations = ConversationRegistry(self)
        self.speech = SpeechLog()
        self.status = [""] * len(self.ids)  # short per-agent text for the TUI
        self.counters = Counters()
        self.led_slots: dict[int, int] = {}  # row -> place behind the robot it follows (crowd/led_slots.py)
        self.events: list[tuple[float, int, str, str]] = []  # (t, agent id, kind, detail), see metrics.SimEvent
        self._plan_failures = 0
        # positions, refreshed once per BT tick as flat float lists: lists of floats are invisible to
        # the garbage collector, a list of 1,000 [x, y] lists per tick kept triggering collections
        self.px: list[float] = []
        self.py: list[float] = []
        self.pos = _Points(self)  # pos[row] -> (x, y)
        self.yaw: list[float] = []
        self.active: list[bool] = []
        self.robot: tuple[float, float, float] | None = None  # x, y, yaw
        self.robot_speed = 0.0
        self.refresh()

    def refresh(self) -> None:
        """Copy the positions leaves read into Python lists (one numpy call instead of one per leaf)."""
        crowd = self.crowd
        n = len(self.ids)
        pos = crowd.pos[:n]
        self.px = pos[:, 0].tolist()
        self.py = pos[:, 1].tolist()
        self.yaw = crowd.yaw[:n].tolist()
        self.active = crowd.active[:n].tolist()
        rp, rv, yaw = crowd.robot_pos, crowd.robot_vel, crowd.robot_yaw  # all None without a robot
        if rp is not None and rv is not None and yaw is not None:
            self.robot = (float(rp[0]), float(rp[1]), yaw)
            self.robot_speed = math.hypot(float(rv[0]), float(rv[1]))
        else:
            self.robot = None
            self.robot_speed = 0.0

    def event(self, kind: str, row: int, detail: str = "") -> None:
        """Log queue_join, queue_served, evacuated, goal_reached for metrics and evaluation."""
        self.events.append((self.clock.now, self.ids[row], kind, detail))

    # ---- intents that a temporary behavior replaces and gives back ------------------------------

    def snapshot(self, row: int) -> Snapshot:
        crowd = self.crowd
        return (crowd.goals(row), int(crowd.mode[row]), float(crowd.desired_speed[row]),
                tuple(float(f) for f in crowd.factors[row]), int(crowd.robot_interaction[row]))

    def restore(self, row: int, snap: Snapshot) -> None:
        crowd = self.crowd
        goals, mode, speed, factors, interaction = snap
        crowd.set_goals(row, goals)
        try:
            crowd.set_mode(row, mode)
        except Exception:  # a field mode without a field cannot come back; fall back to goals
            crowd.set_mode(row, 0)
        crowd.set_speed(row, speed)
        crowd.set_factors(row, *factors)
        crowd.set_robot_interaction(row, interaction)

    # ---- geometry -----------------------------------------------------------------------------

    def resolve_target(self, name: str | None, x: float | None = None, y: float | None = None,
                       goal_id: int | None = None) -> Point:
        """The point of a target: explicit x/y, else a HuNavSim goal id, else the RoI's point in the world."""
        if x is not None and y is not None:
            return (float(x), float(y))
        if goal_id is not None and goal_id in self.goal_table:
            return self.goal_table[goal_id]
        if name and self.world is not None:
            try:
                roi = self.world.roi(name)
            except Exception as exc:  # WorldError lists the known names
                raise BTError(f"target {name!r}: {exc}") from None
            return (float(roi.point[0]), float(roi.point[1]))
        raise BTError(f"target {name!r} has no x/y ports and no world is loaded to resolve it")

    def is_free(self, x: float, y: float, clearance: float = 0.3) -> bool:
        if self.grid is not None:
            return bool(self.grid.is_free(x, y))
        if self.walls.shape[0] == 0:
            return True
        return _distance_to_walls(self.walls, x, y) >= clearance

    def nearest_free(self, x: float, y: float) -> Point:
        if self.grid is not None:
            found = self.grid.nearest_free(x, y)
            if found is not None:
                return (float(found[0]), float(found[1]))
        return (float(x), float(y))

    def plan(self, start: Sequence[float], goal: Sequence[float]) -> list[Point]:
        """Points to walk through to `goal` (start excluded, goal included): Theta* when a grid is loaded."""
        gx, gy = float(goal[0]), float(goal[1])
        if self.planner is None:
            return [(gx, gy)]
        sx, sy = float(start[0]), float(start[1])
        if self.planner.segment_is_free(sx, sy, gx, gy):
            return [(gx, gy)]
        try:
            path = self.planner.plan((sx, sy), (gx, gy))
        except Exception:  # PlanningError: unreachable from here (pushed into a corner); walk straight
            self._plan_failures += 1
            return [(gx, gy)]
        return [(float(p[0]), float(p[1])) for p in path[1:]]

    def sees(self, start: Sequence[float], goal: Sequence[float]) -> bool:
        """Straight walk possible (no occupied cell on the segment); True without a planner."""
        if self.planner is None:
            return True
        return bool(self.planner.segment_is_free(float(start[0]), float(start[1]), float(goal[0]), float(goal[1])))

    def rejoin(self, start: Sequence[float], waypoints: Sequence[Point], goal: Sequence[float]) -> list[Point]:
        """Route back onto planned waypoints after an interruption: from the furthest waypoint in
        sight, else a fresh plan (Theta* costs tens of milliseconds on a large floor)."""
        goal = (float(goal[0]), float(goal[1]))
        points = [*waypoints, goal]
        for j in range(len(points) - 1, -1, -1):
            if self.sees(start, points[j]):
                return [(float(x), float(y)) for x, y in points[j:]]
        return self.plan(start, goal)

    # ---- agents -------------------------------------------------------------------------------

    def members_of(self, agent_id: int) -> tuple[int, ...]:
        return self.groups.get(agent_id, (agent_id,))

    def partner_of(self, row: int) -> int | None:
        """Row of the agent an agent-targeted node means when no id was written: the group's first other
        member, else the nearest active agent."""
        agent_id = self.ids[row]
        for other in self.members_of(agent_id):
            if other != agent_id and other in self.row_of:
                return self.row_of[other]
        return self.nearest_agent(row)

    def nearest_agent(self, row: int) -> int | None:
        crowd = self.crowd
        n = len(self.ids)
        if n < 2:
            return None
        pos = crowd.pos[:n]
        d2 = np.sum((pos - pos[row]) ** 2, axis=1)
        d2[row] = np.inf
        d2[~crowd.active[:n]] = np.inf
        best = int(np.argmin(d2))
        return None if not np.isfinite(d2[best]) else best

    def row(self, agent_id: object, what: str = "agent_id") -> int:
        """The crowd row of an agent id read from a port (an int, or text from a blackboard entry)."""
        row = None
        if isinstance(agent_id, (int, float, str)):
            try:
                row = self.row_of.get(int(agent_id))
            except (ValueError, OverflowError):
                pass
        if row is None:
            raise BTError(f"{what}={agent_id!r} is not an agent of this scenario "
                          f"(ids {min(self.ids, default=0)}..{max(self.ids, default=0)})")
        return row


class _Points:
    __slots__ = ("_sim",)

    def __init__(self, sim: SimContext):
        self._sim = sim

    def __getitem__(self, row: int) -> tuple[float, float]:
        return (self._sim.px[row], self._sim.py[row])


class AgentContext:
    """Per-agent view handed to each leaf: its crowd row and id plus the shared SimContext."""

    __slots__ = ("sim", "row", "agent_id")

    def __init__(self, sim: SimContext, row: int):
        self.sim = sim
        self.row = row
        self.agent_id = sim.ids[row]


def _distance_to_walls(walls: np.ndarray, x: float, y: float) -> float:
    ax, ay, bx, by = walls[:, 0], walls[:, 1], walls[:, 2], walls[:, 3]
    dx, dy = bx - ax, by - ay
    length2 = dx * dx + dy * dy
    t = np.clip(((x - ax) * dx + (y - ay) * dy) / np.where(length2 > 0, length2, 1.0), 0.0, 1.0)
    px, py = ax + t * dx - x, ay + t * dy - y
    return float(np.sqrt(np.min(px * px + py * py)))
