"""A look "as the robot passes them" counted in each person's own time near the passing robot, once they
are in place.

"Six patients queue at the pharmacy and look at the robot as it passes": the look was counted from t = 0.1 s,
while the patients were still walking to the queue and the robot came by them on the way; a glance then
counted as the look "as it passes" the queue. Now each member's window opens when they are in place (their
first queue join; without one, from when they stand still STILL_FOR seconds; people who never stand are
counted from the start) and is the frames the robot passes them then. The verdict says when the robot
passed them and when each of them first looked.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from grove_tui.scenario.events import SimEvent

STANDING = 0.2  # m/s
STILL_FOR = 2.0  # seconds standing that put someone in place


class PassingWindow:
    """The frames of a look claimed as the robot passes: per member, in sight and passing, and looking."""

    def __init__(self) -> None:
        self.t: list[np.ndarray] = []
        self.sight: list[np.ndarray] = []
        self.looking: list[np.ndarray] = []
        self.speed: list[np.ndarray] = []
        self.first_look: dict[int, float] = {}

    def add(self, t: np.ndarray, sight: np.ndarray, looking: np.ndarray, speed: np.ndarray) -> None:
        self.t.append(np.asarray(t, dtype=float))
        self.sight.append(np.asarray(sight, dtype=bool))
        self.looking.append(np.asarray(looking, dtype=bool))
        self.speed.append(np.nan_to_num(np.asarray(speed, dtype=float), nan=np.inf))

    def in_place(self, ids: Sequence[int], events: dict[int, list[SimEvent]]) -> np.ndarray | None:
        """(M,) the time each member is in place from, or None with no frames."""
        if not self.t:
            return None
        t = np.concatenate(self.t)
        speed = np.concatenate(self.speed)
        dt = float(np.median(np.diff(t))) if t.size > 1 else 0.1
        need = max(1, int(round(STILL_FOR / max(dt, 1e-6))))
        out = np.zeros(len(ids))
        for j, agent in enumerate(ids):
            joins = [e.t for e in events.get(agent, ()) if e.kind == "queue_join"]
            if joins:
                out[j] = min(joins)
                continue
            still = speed[:, j] < STANDING
            run = np.convolve(still.astype(int), np.ones(need, dtype=int), mode="valid")
            k = np.flatnonzero(run >= need)
            out[j] = float(t[k[0]]) if k.size else 0.0
        return out

    def counted(self, since: np.ndarray, dt: float) -> tuple[np.ndarray, np.ndarray, np.ndarray, list[float],
                                                             list[float]]:
        """(in sight, facing, longest look in frames, [first, last] passed, [first, last] looked) per member,
        from each one's `since` on."""
        t = np.concatenate(self.t)
        placed = t[:, None] >= since[None, :]
        sight = np.concatenate(self.sight) & placed
        looking = np.concatenate(self.looking) & placed
        run = np.zeros(sight.shape[1])
        longest = np.zeros(sight.shape[1])
        for row in looking:
            run = np.where(row, run + 1, 0)
            longest = np.maximum(longest, run)
        passed_rows = sight.any(axis=1)
        looked_rows = looking.any(axis=1)
        passed = [float(t[passed_rows][0]), float(t[passed_rows][-1])] if passed_rows.any() else []
        looked = [float(t[looked_rows][0]), float(t[looked_rows][-1])] if looked_rows.any() else []
        self.first_look = {j: float(t[np.flatnonzero(looking[:, j])[0]]) for j in range(looking.shape[1])
                           if looking[:, j].any()}
        return sight.sum(axis=0).astype(float), looking.sum(axis=0).astype(float), longest, passed, looked

    def said(self, ids: Sequence[int], since: np.ndarray) -> str:
        """When each member was in place and first looked, for the claim's evidence."""
        parts = []
        for j, agent in enumerate(ids):
            look = self.first_look.get(j)
            parts.append(f"{agent}: in place t = {since[j]:.1f} s, " +
                         (f"looked t = {look:.1f} s" if look is not None else "did not look"))
        return " (counted from each one in place; " + "; ".join(parts) + ")"
