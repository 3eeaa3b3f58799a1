"""Where people will stand still together: queue lines and conversation circles, read from their trees.

The robot's planner treats these as obstacles (issue 21 item 13): a path that runs through a queue
or a circle of talking people is planned around it. The geometry is the runtime's own: the queue's
heading, slots and the spots served people step to come from `crowd.coordination` and
`crowd.leaves.grove` evaluated on the occupancy grid (the simulation asks the same grid), and a circle's
radius is HuNavSim's `conversation_radius`.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from typing import TypedDict

import numpy as np

from grove_tui.crowd.coordination import ServiceQueue, conversation_radius, queue_line_direction, queue_spacing
from grove_tui.bt.format.document import TreeDocument, TreeElement
from grove_tui.crowd.leaves.grove import aside_spot
from grove_tui.bt.format.manifest import NODES
from grove_tui.world.model import World
from grove_tui.navigation.grid import OccupancyGrid

Point = tuple[float, float]

PERSON_RADIUS = 0.35  # the body radius planning gives every agent (AgentSpec.radius)
# Room the robot leaves between its body and a standing person's: the personal-space band the
# HuNavSim evaluator counts intrusions in starts at 0.45 m from the person's centre.
PASSING_MARGIN = 0.3


@dataclass(frozen=True)
class Formation:
    """People standing still together: `kind` "queue" or "conversation" at `name` (the RoI)."""

    kind: str
    name: str
    line: tuple[Point, ...]  # queue: service point, then every slot; conversation: the centre alone
    spots: tuple[Point, ...] = ()  # queue: where served people step aside to stand
    radius: float = PERSON_RADIUS  # queue: a body; conversation: the circle plus a body

    def describe(self) -> str:
        if self.kind == "queue":
            return f"the queue at {self.name} ({len(self.line)} places)"
        return f"the conversation at {self.name}"


class GridSpace:
    """The occupancy grid answering what the runtime's coordination code asks of the simulation."""

    def __init__(self, world: World, grid: OccupancyGrid) -> None:
        self.world = world
        self.grid = grid

    def is_free(self, x: float, y: float, clearance: float = 0.3) -> bool:
        return bool(self.grid.is_free(x, y))

    def nearest_free(self, x: float, y: float) -> Point:
        found = self.grid.nearest_free(x, y)
        return (float(found[0]), float(found[1])) if found is not None else (float(x), float(y))


def _number(element: TreeElement, port: str) -> float:
    text = element.get(port)
    if text is None:
        spec = NODES[element.id].port(port)
        return float(spec.default) if spec is not None and spec.default is not None else 0.0
    return float(text)


def _point(world: World, element: TreeElement, name: str | None, x_port: str = "x", y_port: str = "y") -> Point | None:
    x, y = element.get(x_port), element.get(y_port)
    if x is not None and y is not None:
        return (float(x), float(y))
    if name and world is not None:
        try:
            roi = world.roi(name)
        except Exception:
            return None
        return (float(roi.point[0]), float(roi.point[1]))
    return None


class _QueueTally(TypedDict):
    spacing: float
    people: int
    staying: int  # people whose tree ends in the queue: served, they stand aside


class _CircleTally(TypedDict):
    name: str
    people: int


def predict_formations(world: World, grid: OccupancyGrid, trees: Iterable[TreeDocument], goals: Sequence[Point] = ()) -> list[Formation]:
    """Every queue and conversation circle the agents' trees will form, in the order they first appear."""
    space = GridSpace(world, grid)
    queues: dict[tuple[str, Point], _QueueTally] = {}
    circles: dict[Point, _CircleTally] = {}
    for document in trees:
        elements = list(document.nodes())
        last_leaf = next((e for e in reversed(elements) if not e.children), None)
        for element in elements:
            if element.id == "Queue":
                name = element.get("service_point") or "queue"
                point = _point(world, element, name)
                if point is None:
                    continue
                entry = queues.setdefault((name, point), {"spacing": _number(element, "spacing"), "people": 0,
                                                          "staying": 0})
                entry["people"] += 1
                # A tree that ends with its queue leaves the served person standing beside the line.
                entry["staying"] += element is last_leaf
            elif element.id in ("Converse", "ConversationFormation"):
                centre = _conversation_centre(world, element, goals)
                if centre is None:
                    continue
                circle = circles.setdefault(centre, {"name": element.get("target") or "a spot", "people": 0})
                circle["people"] += 1
    formations = []
    for (name, point), entry in queues.items():
        spacing = queue_spacing(entry["spacing"], [PERSON_RADIUS])
        direction, free_length = queue_line_direction(space, name, point, spacing)
        queue = ServiceQueue(name, point, direction, spacing, 0.0, free_length, space)
        slots = tuple(queue.slot_point(k) for k in range(entry["people"]))
        spots = tuple(aside_spot(space, queue) for _ in range(entry["staying"]))
        formations.append(Formation("queue", name, slots, spots))  # slot 0 is the service point
    for centre, circle in circles.items():
        radius = conversation_radius(circle["people"]) + PERSON_RADIUS
        formations.append(Formation("conversation", circle["name"], (centre,), radius=radius))
    return formations


def _conversation_centre(world: World, element: TreeElement, goals: Sequence[Point]) -> Point | None:
    if element.id == "Converse":
        return _point(world, element, element.get("target"))
    centre = _point(world, element, None, "center_x", "center_y")
    goal_id = element.get("goal_id")
    if centre is None and goal_id is not None and 1 <= int(goal_id) <= len(goals):
        centre = (float(goals[int(goal_id) - 1][0]), float(goals[int(goal_id) - 1][1]))
    return centre


def formation_distance(formation: Formation, points: np.ndarray) -> np.ndarray:
    """Distance from each of `points` (N, 2) to the nearest body of the formation (0 inside one)."""
    points = np.asarray(points, dtype=float).reshape(-1, 2)
    best = np.full(len(points), np.inf)
    line = np.asarray(formation.line, dtype=float)
    pieces = [(line[i], line[i + 1]) for i in range(len(line) - 1)] or [(line[0], line[0])]
    pieces += [(np.asarray(s, float), np.asarray(s, float)) for s in formation.spots]
    for a, b in pieces:
        ab = b - a
        length2 = float(ab @ ab)
        t = np.zeros(len(points)) if length2 == 0.0 else np.clip((points - a) @ ab / length2, 0.0, 1.0)
        nearest = a + t[:, None] * ab
        best = np.minimum(best, np.hypot(*(points - nearest).T))
    return np.maximum(best - formation.radius, 0.0)


def block_formations(grid: OccupancyGrid, formations: Sequence[Formation], clearance: float) -> OccupancyGrid:
    """A copy of the grid with every cell closer than `clearance` to a formation's bodies occupied."""
    occupied = grid.occupied.copy()
    res = float(grid.resolution)
    reach = clearance + max((f.radius for f in formations), default=0.0)
    for formation in formations:
        pts = np.asarray([*formation.line, *formation.spots], dtype=float)
        (r0, c0), (r1, c1) = (grid.world_to_cell(float(pts[:, 0].min() - reach), float(pts[:, 1].min() - reach)),
                              grid.world_to_cell(float(pts[:, 0].max() + reach), float(pts[:, 1].max() + reach)))
        r0, c0 = max(r0, 0), max(c0, 0)
        r1, c1 = min(r1, grid.height - 1), min(c1, grid.width - 1)
        if r1 < r0 or c1 < c0:
            continue
        rows, cols = np.mgrid[r0:r1 + 1, c0:c1 + 1]
        centres = np.column_stack([grid.origin[0] + (cols.ravel() + 0.5) * res,
                                   grid.origin[1] + (rows.ravel() + 0.5) * res])
        near = formation_distance(formation, centres) < clearance
        occupied[rows.ravel()[near], cols.ravel()[near]] = True
    return dataclasses.replace(grid, occupied=occupied, _nearest=None)


def formations_at(formations: Sequence[Formation], point: Point, clearance: float) -> list[Formation]:
    """The formations whose blocked area holds `point` (a robot asked to start or stop there)."""
    return [f for f in formations if float(formation_distance(f, np.asarray([point]))[0]) < clearance]


def nearest_formation_gap(formations: Sequence[Formation], path: Sequence[Point], step: float = 0.05) -> float:
    """The smallest distance between the path (sampled every `step` m) and a formation's bodies."""
    if not formations or len(path) == 0:
        return math.inf
    samples = [np.asarray(path[0], float)]
    for a, b in zip(path, path[1:]):
        a_, b_ = np.asarray(a, float), np.asarray(b, float)
        n = max(1, int(math.ceil(math.dist(a, b) / step)))
        samples.extend(a_ + (b_ - a_) * (k / n) for k in range(1, n + 1))
    points = np.asarray(samples)
    return float(min(formation_distance(f, points).min() for f in formations))
