"""A robot that passes a place where people queue or stand passes beside them, not through them.

"... while the robot passes the ticket office" (station): the robot's way was made to pass by the ticket
office's own point, which is the head of the queue standing there, so the planner had "no way around" and the
robot drove within 0.1 m of the service point, through the people queueing. The point a robot passes a
place by is now at the edge of what stands there (`beside`: the nearest free floor outside every queue and
conversation, with the robot's clearance), and the report checks the run: the robot never came closer than
BESIDE to any of the people standing there (`beside_claims`, the "robot_beside" claim, with the figure).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import replace

import numpy as np

from grove_tui.scenario.reach import PASS_AT
from grove_tui.generation.draft import place_of
from grove_tui.generation.formations import PASSING_MARGIN, PERSON_RADIUS, Formation, formations_at
from grove_tui.language.model import PromptReading, RobotReading
from grove_tui.navigation.grid import OccupancyGrid
from grove_tui.scenario.model import RobotSpec
from grove_tui.scenario.report import Claim, RobotGrounding

Point = tuple[float, float]
ROBOT_RADIUS = 0.3  # RobotSpec.radius
# metres between the robot's centre and a standing person's: bodies apart with half the passing margin to
# spare (PASSING_MARGIN is what planning leaves; the run may shave a little of it)
BESIDE = round(ROBOT_RADIUS + PERSON_RADIUS + PASSING_MARGIN / 2, 2)
_STAYING_NODES = ("Queue", "Wait", "Converse", "LookAtRobot", "SitDown", "Sit")


def beside(spots: Sequence[Point], formations: Sequence[Formation], clearance: float,
           blocked: OccupancyGrid | None) -> list[Point]:
    """Each spot the robot passes by, moved to the nearest free floor of the `blocked` grid (queues and
    circles blocked with `clearance`) when it lies inside a formation; others as they are."""
    if blocked is None or not formations:
        return list(spots)
    out: list[Point] = []
    for p in spots:
        if not formations_at(formations, p, clearance):
            out.append(p)
            continue
        found = blocked.nearest_free(p[0], p[1])
        out.append((round(float(found[0]), 3), round(float(found[1]), 3)) if found is not None else p)
    return out




def _stands_at(group: object, place: str, reading: PromptReading) -> bool:
    tree = getattr(group, "tree", None)
    if tree is None:
        return False
    for node in tree.walk():
        if node.node == "Queue" and place_of(node, "service_point") == place:
            return True
    index = getattr(group, "reading_index", None)
    if index is None or index >= len(reading.groups):
        return False
    r = reading.groups[index]
    return place in (r.location, r.destination) and any(n.node in _STAYING_NODES for n in tree.walk())


def beside_claims(row: RobotGrounding | None, asked: RobotReading | None, groups: Sequence[object],
                  reading: PromptReading, robot: RobotSpec | None, robot_seconds: float) -> RobotGrounding | None:
    """The robot's row with a "robot_beside" claim for each place it passes where people queue or stand, and
    its "robot_via" of that place counted at the edge of the people there (as far as its planned way passes
    the place's point, up to PASS_AT)."""
    if row is None or asked is None or robot is None or asked.task not in ("cross", "patrol"):
        return row
    claims = list(row.claims)
    path = np.asarray(list(getattr(robot, "path", ()) or (robot.start, robot.goal)), dtype=float).reshape(-1, 2)
    for v in asked.via:
        if v in (asked.destination, asked.location):
            continue
        members = tuple(m for g in groups if _stands_at(g, v, reading) for m in getattr(g, "member_ids", ()))
        if not members:
            continue
        for i, c in enumerate(claims):
            if c.kind == "robot_via" and c.place == v and c.point is not None:
                gap = _gap(path, c.point) + 0.5
                if c.radius < gap <= PASS_AT:
                    claims[i] = replace(c, radius=round(gap, 2), plan=c.plan + f", at the edge of the people there "
                                        f"({gap - 0.5:.1f} m from its point)")
        if any(c.kind == "robot_passes" and set(c.partners) & set(members) for c in claims):
            continue  # their passing has its claim already (through them, or past them: past_queue.py)
        claims.append(Claim("robot_beside", f"pass beside the people at {v}, not into them",
                            f"pass {v} at the edge of the people there", place=v, partners=members,
                            distance=BESIDE, needs_seconds=round(robot_seconds * 1.3 + 10.0, 1)))
    if tuple(claims) == tuple(row.claims):
        return row
    return replace(row, claims=tuple(claims))




def _gap(path: np.ndarray, point: Point) -> float:
    """The nearest the polyline `path` comes to `point`."""
    if len(path) == 1:
        return math.dist(tuple(path[0]), point)
    a, b = path[:-1], path[1:]
    ab = b - a
    t = np.clip(((point[0] - a[:, 0]) * ab[:, 0] + (point[1] - a[:, 1]) * ab[:, 1]) /
                np.maximum((ab ** 2).sum(axis=1), 1e-12), 0.0, 1.0)
    q = a + t[:, None] * ab
    return float(np.hypot(q[:, 0] - point[0], q[:, 1] - point[1]).min())
