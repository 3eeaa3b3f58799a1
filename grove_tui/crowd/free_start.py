"""Where an agent pressed into a wall band sees from: the nearest free cell on its side of the wall.

The crowd lets people be pushed into the band of occupied cells along a wall (the planner's grid is
inflated; the social force keeps bodies off the wall itself). "Can I see my goal from here" asked from
such a cell is always "no": a follower of the robot beside the security door was sent round a planned
way from wherever the planner snapped its start, walked along the wrong side of the wall, and its
party waited for it. A start (or a goal place) in a wall band is moved to the nearest free cell that
sees the point the agent is heading for, else the nearest free cell, before sight and plans are asked.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

from grove_tui.crowd.context import Point, SimContext

SEARCH = 1.0  # metres round an occupied point searched for a free cell that sees where the agent heads
STEP = 0.1  # metres between the points tried


def free_point(sim: SimContext, point: Sequence[float], toward: Sequence[float] | None = None) -> Point:
    """`point` when it is free floor (or no grid is loaded), else the nearest free point within SEARCH
    that sees `toward` (when given), else the nearest free cell."""
    x, y = float(point[0]), float(point[1])
    if sim.grid is None or sim.is_free(x, y):
        return (x, y)
    if toward is not None:
        best: tuple[float, Point] | None = None
        n = int(SEARCH / STEP)
        for i in range(-n, n + 1):
            for j in range(-n, n + 1):
                d = math.hypot(i, j) * STEP
                if d > SEARCH or (best is not None and d >= best[0]):
                    continue
                cand = (x + i * STEP, y + j * STEP)
                if sim.is_free(*cand) and sim.sees(cand, toward):
                    best = (d, cand)
        if best is not None:
            return best[1]
    return sim.nearest_free(x, y)
