"""How far a person walks to each of their places: the paths planning gave their tree, leg by leg.

The grounding report gives each reach, stay, queue, leave and evacuate claim the seconds a run must
last before its outcome can be told (`needs_seconds`). Straight legs times a fixed detour factor
misjudged a route round a concourse or down a corridor's dog-leg by half (exam room 1 to ward b in
the hospital: 16 m as the crow flies, 72 m walked). Planning injects into every navigation node the
waypoints the agent then walks (`waypoints.plan_waypoints`), and an evacuee under a field follows
its group's path to the exit: those are the distances a run takes. A leg nothing planned (the walk
to a queue's place, a leg after following someone, a scenario planned without a planner) is the
straight line times UNPLANNED_DETOUR, as every leg was before.

    routes = planned_routes(scenario.agents, trees, planning_mode(preset))
    walk = RouteWalk(agent.start, routes.get(agent.id, ()))
    walk.to(point)          # metres to the first leg ending there, weighted
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Literal

from grove_tui.bt.format.document import TreeDocument, TreeElement
from grove_tui.bt.format.manifest import NODES
from grove_tui.bt.format.ports import parse_point_list
from grove_tui.generation.waypoints import DRIFTING, WAYPOINTS_PORT, navigation_tags, relocating_tags
from grove_tui.scenario.model import AgentSpec

Point = tuple[float, float]
PlanningMode = Literal["waypoints", "field", "none"]

# A planned path walked among others is longer in time than at free speed: passing people and the
# robot, slowing at doors and corners, the density slowdown. 1.2 covers the runs the grounding suite
# measures; a person still walking on when a run ends is told apart from one stuck (outcomes.py).
PATH_MARGIN = 1.2
# A leg nothing planned, as the crow flies: the detour factor every leg had before paths were read.
UNPLANNED_DETOUR = 1.5
SAME_POINT = 0.05  # metres: a target and a leg's end written from the same point (3 decimals each way)


@dataclass(frozen=True)
class Leg:
    """One leg of an agent's tree in tick order: where it ends and the metres walked to get there."""

    target: Point
    metres: float
    planned: bool  # the planned path's length; False: the straight line, nothing was planned

    @property
    def weighted(self) -> float:
        """Metres as time at the agent's pace will count them (a margin on a path, a detour on a line)."""
        return self.metres * (PATH_MARGIN if self.planned else UNPLANNED_DETOUR)


def planning_mode(velocity: str, planner_enabled: bool) -> PlanningMode:
    """What planning gave the trees under a preset: waypoints, a field to the exit, or nothing."""
    if velocity == "field":
        return "field"
    return "waypoints" if planner_enabled else "none"


def planned_routes(agents: Sequence[AgentSpec], trees: Mapping[str, TreeDocument],
                   mode: PlanningMode) -> dict[int, tuple[Leg, ...]]:
    """Agent id -> its legs, from its planned tree (`mode` says what planning wrote into it)."""
    routes: dict[int, tuple[Leg, ...]] = {}
    for agent in agents:
        document = trees.get(agent.tree)
        if document is None:
            continue
        # under a field, a follower's goals are its group's path to the exit (planning.plan_operational)
        field_path = tuple(agent.goals) if mode == "field" else ()
        routes[agent.id] = planned_legs(document, agent.start, waypoints=mode == "waypoints", field_path=field_path)
    return routes


def planned_legs(document: TreeDocument, start: Point, *, waypoints: bool,
                 field_path: Sequence[Point] = ()) -> tuple[Leg, ...]:
    """The legs of `document`'s trees in tick order, as `waypoints.plan_waypoints` walked them.

    `waypoints`: the navigation nodes carry planned waypoints (an empty port is then a straight leg
    in line of sight); `field_path`: the path a FollowVelocityField node follows to its exit."""
    navigating, relocating = navigation_tags(), relocating_tags()
    legs: list[Leg] = []
    for tree in document.trees.values():
        origin: Point = (float(start[0]), float(start[1]))
        position: Point | None = origin
        last = origin  # where it was last known to be, for a leg from wherever a drift left it
        for element in tree.walk():
            if element.id in DRIFTING:
                position = None
                continue
            if element.id not in navigating and element.id not in relocating:
                continue
            target = _point(element)
            if target is None:
                continue
            here = position if position is not None else last
            if element.id == "FollowVelocityField" and len(field_path) > 0 and position is not None:
                path = (position, *field_path)
                legs.append(Leg(target, _length(path), True))
            elif element.id in navigating and waypoints and position is not None:
                path = (position, *_waypoints(element), target)
                legs.append(Leg(target, _length(path), True))
            else:
                legs.append(Leg(target, math.dist(here, target), False))
            position = last = target
    return tuple(legs)


class RouteWalk:
    """Walks an agent's legs target by target, summing their weighted metres."""

    def __init__(self, start: Point, legs: Sequence[Leg]) -> None:
        self.here: Point = start
        self.metres = 0.0
        self._legs = tuple(legs)
        self._next = 0

    def to(self, point: Point) -> float:
        """On to the next leg that ends at `point` (every leg before it walked too); a point no leg ends
        at is a straight unplanned leg from here. Returns the weighted metres so far."""
        for j in range(self._next, len(self._legs)):
            if math.dist(self._legs[j].target, point) <= SAME_POINT:
                self.metres += sum(leg.weighted for leg in self._legs[self._next:j + 1])
                self._next = j + 1
                self.here = point
                return self.metres
        return self.straight_to(point)

    def straight_to(self, point: Point) -> float:
        self.metres += UNPLANNED_DETOUR * math.dist(self.here, point)
        self.here = point
        return self.metres

    def to_end(self) -> float:
        """Every leg left: the whole route."""
        self.metres += sum(leg.weighted for leg in self._legs[self._next:])
        self._next = len(self._legs)
        if self._legs:
            self.here = self._legs[-1].target
        return self.metres


def _point(element: TreeElement) -> Point | None:
    x, y = element.get("x"), element.get("y")
    if x is None or y is None or element.id not in NODES:
        return None
    try:
        return float(x), float(y)
    except ValueError:  # a blackboard pointer: planning refuses those, nothing to measure
        return None


def _waypoints(element: TreeElement) -> tuple[Point, ...]:
    try:
        return parse_point_list(element.get(WAYPOINTS_PORT) or "")
    except ValueError:
        return ()


def _length(path: Sequence[Point]) -> float:
    return sum(math.dist(a, b) for a, b in zip(path, path[1:]))
