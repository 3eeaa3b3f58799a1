"""A robot whose clause goes past people who queue (or stand talking) passes beside them, not through them.

"Eight patients queue at the pharmacy while the robot drives past them to the cafeteria" (hospital): the
reading names the patients as people the robot passes (RobotReading.passes) with no word of how, and
planning treated every such passing as "drives through the queue" (robot_passing.through_formations: the
queue no obstacle, the way through its gap): the robot drove into the line, 0.6 m from a patient, while the
report read "passes through the patients" ✓ and "passes beside the people at pharmacy" ✗. Now the robot's
own words say how (language/passing_manner.py): through them as before, else the formation stays an
obstacle and the robot's way passes beside its first and its last place (`beside_points`, moved to the
free floor at its edge by beside_queue.beside), so it goes by the whole line and on past the last of them.
The report makes one claim of that passing (reconcile's robot_passes with `low`: beside them, the nearest it
came to someone standing there between BESIDE and PASS_BY), not a second robot_beside that disagrees.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import replace

import numpy as np

from grove_tui.scenario.reach import PASS_BY
from grove_tui.generation.beside_queue import BESIDE
from grove_tui.generation.formations import Formation
from grove_tui.generation.robot_passing import passed_zones
from grove_tui.language.model import PromptReading, RobotReading
from grove_tui.navigation.grid import OccupancyGrid
from grove_tui.language.passing_manner import passes_through
from grove_tui.scenario.report import Claim
from grove_tui.world.model import World

Point = tuple[float, float]


def passes_beside(reading: PromptReading | None) -> bool:
    """Whether the robot's clause passes its people beside them (not through them)."""
    return reading is not None and reading.robot is not None and bool(reading.robot.passes) and \
        not passes_through(reading.robot)


SIDE = 1.6  # metres from the line's centre to the robot's: BESIDE with room for people who sway in place


def beside_points(reading: PromptReading | None, world: World, formations: Sequence[Formation],
                  blocked: OccupancyGrid | None) -> list[Point]:
    """For each formation where people the robot passes beside stand: points SIDE off its line, by its
    second place (the first is being served) and a place beyond its last, on the side with free floor and
    SIDE from where served people step aside to stand; a conversation: the nearest free floor to its centre (beside_queue.beside)."""
    if not passes_beside(reading):
        return []
    zones = set(passed_zones(reading, world).values())
    out: list[Point] = []
    for f in formations:
        if not any(_zone(world, p) in zones for p in f.line):
            continue
        slots = [np.asarray(p, dtype=float) for p in (f.line[1:] if f.kind == "queue" and len(f.line) > 1 else f.line)]
        if f.kind != "queue" or len(f.line) < 2:
            out.append((float(slots[0][0]), float(slots[0][1])))
            continue
        head = np.asarray(f.line[0], dtype=float)
        along = slots[-1] - head
        norm = float(np.hypot(*along))
        if norm < 1e-6:
            continue
        u = along / norm
        n = np.array([-u[1], u[0]])
        back = slots[-1] + u * 0.8
        best: list[Point] | None = None
        for off in (SIDE, SIDE + 0.4, SIDE + 0.8, SIDE + 1.2):  # the nearest side with free floor
            for side in (1.0, -1.0):
                # from its second place back (the first is being served), the first clear of where served
                # people step aside to stand (one stood 0.8 m from the robot there)
                fronts = [e + side * off * n for e in slots[min(1, len(slots) - 1):]]
                end = back + side * off * n
                if not self_free(blocked, end, f.spots):
                    continue
                front = next((p for p in fronts if self_free(blocked, p, f.spots)), None)
                if front is not None:
                    best = [(round(float(p[0]), 3), round(float(p[1]), 3)) for p in (front, end)]
                    break
            if best is not None:
                break
        ends = [slots[min(1, len(slots) - 1)], back]
        out.extend(best if best is not None else [(float(e[0]), float(e[1])) for e in ends])
    return out


def self_free(blocked: OccupancyGrid | None, p: np.ndarray, aside: Sequence[Point]) -> bool:
    """Whether the robot may pass by `p`: free floor, SIDE from where served people stand aside."""
    return (blocked is None or blocked.is_free(float(p[0]), float(p[1]))) and \
        all(math.dist((float(p[0]), float(p[1])), q) >= SIDE for q in aside)


def _zone(world: World, p: Point) -> str | None:
    zone = world.zone_at(p[0], p[1])
    return zone.name if zone is not None else None


def past_or_through(claim: Claim, robot: RobotReading | None, label: str) -> Claim:
    """The robot_passes claim as the robot's words say it: through them (within PASSING_DISTANCE of one of
    them), or past them: beside them, the nearest it comes to one of them between BESIDE and PASS_BY."""
    if robot is None or passes_through(robot):
        return claim
    zone = claim.zone or "their place"
    return replace(claim, asked=f"past the {label}s in {zone}, beside them, not into them",
                   plan=f"drive past them in {zone}, at the edge of where they stand", distance=PASS_BY, low=BESIDE)
