"""Reached means arrived: someone who starts at the place they are asked to go has not reached it.

"The robot leads a visitor to the computer lab" with the visitor placed in the lab was ✓ "reached by
t = 0.1 s". A member (or the robot) counts as arriving only at a frame where they are at the place
after having been somewhere else: one who starts there must leave it and come back (a longer run may
still show that), and the verdict says how many started there.
"""

from __future__ import annotations

import numpy as np


class Arrivals:
    """Per member: whether they started at the place (at their first frame in the run) and whether they
    have been away from it since."""

    def __init__(self, members: int) -> None:
        self.started_in = np.full(members, -1, dtype=np.int8)  # -1: not seen yet, 0: started elsewhere, 1: there
        self.been_out = np.zeros(members, dtype=bool)

    def arrived(self, inside: np.ndarray, present: np.ndarray) -> np.ndarray:
        """(F, M) the frames of a chunk where each member is at the place as an arrival, not a start."""
        if inside.size == 0:
            return inside
        first = np.argmax(present, axis=0)
        unseen = (self.started_in < 0) & present.any(axis=0)
        cols = np.flatnonzero(unseen)
        self.started_in[cols] = inside[first[cols], cols].astype(np.int8)
        away = present & ~inside
        been_out = self.been_out[None, :] | np.logical_or.accumulate(away, axis=0)
        self.been_out |= away.any(axis=0)
        return inside & ((self.started_in != 1)[None, :] | been_out)

    def started_there(self, pending: np.ndarray | None = None) -> int:
        """How many started at the place (of those `pending`, when given) and have not come back to it."""
        there = self.started_in == 1
        return int((there if pending is None else there & pending).sum())
