"""A queue claim's time counts the people of other groups in the same queue.

"Twenty passengers queue at check-in counter A and a few of them glance at the robot": the subset is
a group of its own that queues at the same counter as the rest, behind them. Its queue claim was timed
as if its three people had the counter to themselves, so the run (sized by the longest claim) ended
before any of them was served and the claim read ✗ "served 0". Every queue claim's `needs_seconds`
adds one service time for each person of the other groups queueing at the same service point (the
worst case: all of them ahead), so the run length covers it, and a shorter run says "not checked".
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Sequence
from dataclasses import replace

from grove_tui.scenario.report import GroupGrounding


def with_shared_queues(groups: Sequence[GroupGrounding], service_time: float = 10.0) -> list[GroupGrounding]:
    """`groups` with every queue claim's needs_seconds covering the other groups' people in its queue."""
    queued: Counter[str] = Counter()
    for g in groups:
        for place in {c.place for c in g.claims if c.kind == "queue" and c.place}:
            queued[place] += len(g.members)
    out = []
    for g in groups:
        claims = tuple(replace(c, needs_seconds=c.needs_seconds + (queued[c.place] - len(g.members)) * service_time)
                       if c.kind == "queue" and c.place and c.needs_seconds is not None
                       and queued[c.place] > len(g.members) else c for c in g.claims)
        out.append(replace(g, claims=claims))
    return out
