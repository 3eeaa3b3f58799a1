"""A robot the sentence gives no task passes the people asked to react to it.

"Six passengers queue at check-in counter A and two of them glance at the robot": the robot's start and goal
were chosen to pass the crowd's starting centre, or the people who only react where the sentence puts them.
People who react around a routine of their own (queueing, waiting, talking) were not looked at: they stand
where their routine takes them (the back of the queue), and the robot's way ran 11.6 m from them, out of a
glance's 10 m, so the claim read ✗ with no cause. The pair is now aimed at where every reacting person
stays (`reacting_points`: their last place, else their start), and planning takes the first of its best
pairs whose planned path comes within `PASS_NEAR` of each of them.
"""

from __future__ import annotations

import math
from collections.abc import Collection, Sequence
from typing import Protocol

import numpy as np
import shapely

from grove_tui.errors import WorldError
from grove_tui.generation.draft import DraftNode
from grove_tui.world.model import World

Point = tuple[float, float]

# metres: the robot's way passes each reacting person this near (well inside a look's 10 m, near the 5 m
# at which a reaction to it sets off)
PASS_NEAR = 4.0
_ROBOT_NODES = ("Robot",)  # LookAtRobot, ApproachRobot, BlockRobot, AvoidRobot, IsRobotClose, IsRobotVisible


class ReactingAgent(Protocol):
    @property
    def id(self) -> int: ...
    @property
    def start(self) -> Point: ...
    @property
    def targets(self) -> list[tuple[str, Point]]: ...
    @property
    def tree(self) -> DraftNode: ...


def reacts_to_robot(tree: DraftNode) -> bool:
    """Whether a tree reacts to the robot (any robot node)."""
    return any(any(word in n.node for word in _ROBOT_NODES) for n in tree.walk())


def reacting_points(agents: Sequence[ReactingAgent], skip: Collection[int] = frozenset()) -> list[Point]:
    """Where each person who reacts to the robot stays: its last place, else its start."""
    out: list[Point] = []
    for a in agents:
        if a.id in skip or not reacts_to_robot(a.tree):
            continue
        x, y = a.targets[-1][1] if a.targets else a.start
        out.append((float(x), float(y)))
    return out


def widest_gap(path: np.ndarray, points: Sequence[Point]) -> float:
    """The farthest any of `points` is from the polyline `path`."""
    if not points:
        return 0.0
    p = np.asarray(path, dtype=float).reshape(-1, 2)
    worst = 0.0
    for x, y in points:
        if len(p) == 1:
            worst = max(worst, math.dist(p[0], (x, y)))
            continue
        a, b = p[:-1], p[1:]
        ab = b - a
        t = np.clip(((x - a[:, 0]) * ab[:, 0] + (y - a[:, 1]) * ab[:, 1]) / np.maximum((ab ** 2).sum(axis=1), 1e-12),
                    0.0, 1.0)
        q = a + t[:, None] * ab
        worst = max(worst, float(np.hypot(q[:, 0] - x, q[:, 1] - y).min()))
    return worst


def unplaced_note(world: World, label: str, spawn: str, reactor_zone: str | None, task: str,
                  route: Sequence[Point]) -> str:
    """Why people who react to the robot keep their start, as the plan shows it: the robot's task (it waits,
    it follows someone) keeps it off their room, or its route does not come into their room, or (only then)
    there is no free floor beside it. "No free floor beside the robot's route" was said of drivers 26 m from a
    robot told to wait at a bus bay."""
    try:
        polygon = world.zone(reactor_zone or spawn).polygon if reactor_zone or spawn else None
    except WorldError:  # not a zone of the world (a door, an entity): no distance to say
        polygon = None
    gap = None
    if polygon is not None and route:
        line = shapely.LineString(route) if len(route) > 1 and len(set(route)) > 1 else shapely.Point(route[0])
        gap = float(line.distance(polygon))
    where = f" ({gap:.1f} m from {reactor_zone or spawn})" if gap is not None else ""
    if task in ("wait", "follow"):
        doing = "waits" if task == "wait" else "follows someone"
        return (f"group '{label}': the robot {doing} as the sentence asks, away from them{where}; they start in "
                f"{spawn} and react only if it comes near")
    if gap is not None and gap > 0.5:
        return (f"group '{label}': the robot's route does not come into {reactor_zone or spawn}{where}; they "
                f"start in {spawn}")
    return f"group '{label}': no free floor beside the robot's route; they start in {spawn}"
