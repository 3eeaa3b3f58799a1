"""A robot that passes people who queue and react to it passes the whole queue, not only its head.

"Six patients queue at the pharmacy and look at the robot as it passes": planning aimed the robot's way at
where each reacting person stays (passing_reactors.reacting_points: their last target), and a queuer's last
target is the service point, so every patient counted as standing at the counter and the way was chosen to
pass the head of the queue; the back of a long line could be out of the look's reach. Each reacting queuer
now counts at a slot of the queue the trees will form (formations.predict_formations: slot 0 the service
point, then back along the line), so the way chosen passes within PASS_NEAR of every place in the line.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

from grove_tui.generation.formations import Formation

Point = tuple[float, float]
_SAME = 0.3  # metres: a reacting point this near a queue's service point stands in that queue


def along_their_queues(points: Sequence[Point], formations: Sequence[Formation]) -> list[Point]:
    """`points` with those at a queue's service point spread over the queue's slots, one each, in order."""
    out = list(points)
    for f in formations:
        if f.kind != "queue" or not f.line:
            continue
        head = f.line[0]
        at = [i for i, p in enumerate(out) if math.dist(p, head) <= _SAME]
        for k, i in enumerate(at):
            out[i] = f.line[min(k, len(f.line) - 1)]
    return out

