"""An aside between the robot and its verb (round 20): "the robot, meanwhile, keeps patrolling", "the
robot, for its part, patrols the corridor", "the robot, as usual, waits by the lift". A short run of
words between commas right after the robot's word, with no verb in it, is no part of what the robot
does: its verb is the one after the aside."""

from __future__ import annotations

from grove_tui.language.sentence import Sentence

_LONGEST = 4  # words inside the aside


def after_aside(s: Sentence, j: int) -> int:
    """The word after an aside that opens with the comma at j ("the robot, meanwhile, patrols": the
    index of "patrols"); j itself when no such aside opens there."""
    if j >= s.n or s.low[j] != ",":
        return j
    for k in range(j + 1, min(s.n, j + 2 + _LONGEST)):
        if s.low[k] == ",":
            inside = range(j + 1, k)
            if k == j + 1 or k + 1 >= s.n or any(s.w[x].pos in ("VERB", "AUX") or s.is_punct(x) for x in inside):
                return j
            return k + 1
        if s.w[k].pos in ("VERB", "AUX") or s.is_punct(k):
            return j
    return j
