"""Waypoint injection: plan every leg between consecutive navigation goals of a behavior tree.

The paper's operational layer: each navigation node (`navigates=True` in the node manifest: GoTo,
Converse, ...) carries its resolved target in the `x`, `y` ports; the legs start -> first target,
first -> second, ... are planned with Theta* and the intermediate points land in the node's
`waypoints` port ("x1,y1;x2,y2", start and target excluded). Nodes that move the agent without a
waypoints port (Queue, FollowVelocityField: resolved `x`, `y` but `navigates=False`) are not planned
but move the start of the next leg to their point. The tree keeps its structure and every
other attribute; the result depends only on the targets and the start, so injecting twice changes
nothing.
"""

from __future__ import annotations

from typing import Protocol

import numpy as np

from grove_tui.bt.format.document import TreeDocument, TreeElement
from grove_tui.bt.format.manifest import NODES
from grove_tui.bt.format.ports import format_point_list
from grove_tui.errors import PlanningError

Point = tuple[float, float]


class _Planner(Protocol):
    """What plans a leg: Theta* or a cache in front of it (generation/planning.py's CachedPlanner)."""

    def plan(self, start: Point, goal: Point, start_label: str = ..., goal_label: str = ...) -> np.ndarray: ...

WAYPOINTS_PORT = "waypoints"


def navigation_tags() -> frozenset[str]:
    return frozenset(name for name, spec in NODES.items() if spec.navigates)


# Nodes that move the agent to wherever the run takes it (behind someone, around a room): a leg after
# one cannot be planned beforehand.
DRIFTING = frozenset({"FollowAgent", "ApproachAgent", "Wander"})


def relocating_tags() -> frozenset[str]:
    """Nodes that leave the agent at their resolved x, y without planned waypoints (Queue, FollowVelocityField)."""
    return frozenset(name for name, spec in NODES.items()
                     if not spec.navigates and spec.port("x") is not None and spec.port("y") is not None)


def _target_point(element: TreeElement) -> tuple[float, float]:
    values = []
    for port in ("x", "y"):
        raw = element.get(port)
        if raw is None:
            raise PlanningError(f"{element.describe()} has no resolved '{port}' port; post-processing must write "
                                f"the target point before planning")
        try:
            values.append(float(raw))
        except ValueError:
            raise PlanningError(f"{element.describe()} port {port}={raw!r} is not a number (a blackboard "
                                f"pointer cannot be planned; post-processing must resolve it)") from None
    return values[0], values[1]


def _target_label(element: TreeElement) -> str:
    for port in ("target", "service_point", "exit", "zone", "name"):
        value = element.get(port)
        if value:
            return value
    return element.id


def plan_waypoints(document: TreeDocument, start: Point, planner: _Planner, start_label: str = "start") -> TreeDocument:
    """Fill the `waypoints` port of every navigation node of every BehaviorTree of `document`, in place.

    `planner` is anything with `plan(start, goal, start_label=..., goal_label=...) -> (K, 2)` (a
    ThetaStarPlanner, or a wrapper going through a PlanCache). Unplannable legs raise PlanningError
    naming both ends. Returns the document.
    """
    navigating = navigation_tags()
    relocating = relocating_tags()
    for tree in document.trees.values():
        position: tuple[float, float] | None = (float(start[0]), float(start[1]))
        position_label = start_label
        for element in tree.walk():
            node_id = element.id
            if node_id in DRIFTING:
                position = None  # where it ends is the run's to say: the next leg is planned from there
                continue
            if node_id in relocating:
                # The next leg starts where this node leaves the agent (e.g. at the queue's counter).
                if element.get("x") is not None and element.get("y") is not None:
                    position, position_label = _target_point(element), _target_label(element)
                continue
            if node_id not in navigating:
                continue
            target = _target_point(element)
            label = _target_label(element)
            if position is None:
                element.set(WAYPOINTS_PORT, "")  # GoTo plans from where it stands when it starts
            else:
                path = planner.plan(position, target, start_label=position_label, goal_label=label)
                element.set(WAYPOINTS_PORT, format_point_list(path[1:-1]))
            position, position_label = target, label
    return document

