"""Words of time said in more than one word (round 28): "every time the robot beeps", "each time it
comes near", "any time the robot passes", "the moment the robot rolls in". The last word of such a
phrase ("time", "moment", "minute", "second", "instant") is a word of time like "whenever" when the
robot's clause follows it."""

from __future__ import annotations

from grove_tui.language.sentence import Sentence

# First words and last words of a phrase of time.
_EVERY = frozenset("every each any the".split())
_TIME_NOUNS = frozenset("time moment minute second instant".split())


def time_phrase_end(s: Sentence, k: int) -> bool:
    """Whether the word at k ends a phrase of time that leads into a clause ("every time", "the
    moment"): only "every/each/any time" or "the moment/minute/second/instant"."""
    if not 1 <= k < s.n or s.low[k] not in _TIME_NOUNS or s.low[k - 1] not in _EVERY:
        return False
    return (s.low[k] == "time") != (s.low[k - 1] == "the")
