"""One more of the people said before, told by an ordinal (round 27): "Have two firefighters stand
by the display and a third at the hydrant", "Put three cleaners in the food court and a fourth by
the fountain", "Post one guard at the door and a second at the lifts". "A third" after two of them
is one more of their kind, as "another" is; it is said "another" before the sentence is parsed, so
the reader's "another" (one more of the group before) reads it."""

from __future__ import annotations

import re

_ORDINALS = {"second": 2, "third": 3, "fourth": 4, "fifth": 5, "sixth": 6, "seventh": 7, "eighth": 8, "ninth": 9,
             "tenth": 10}
_NUMBERS = {"one": 1, "a": 1, "an": 1, "two": 2, "three": 3, "four": 4, "five": 5, "six": 6, "seven": 7, "eight": 8,
            "nine": 9}
# What follows an elliptic ordinal: where they are, or their verb.
_AFTER = ("at|by|in|on|near|beside|behind|outside|inside|next|opposite|under|beneath|upstairs|downstairs|"
          "stands?|waits?|sits?|stays?|lingers?|walks?|heads?|goes|go|patrols?|guards?|mans?|watches|watch|"
          "minds?|covers?|keeps?|over|round|around|to")
_ELLIPTIC = re.compile(r"(?P<join>\band|,)\s+(?:a|the)\s+(?P<ord>" + "|".join(_ORDINALS) + r")\b(?=\s+(?:"
                       + _AFTER + r")\b)", re.IGNORECASE)
_COUNT = re.compile(r"\b(?P<n>" + "|".join(k for k in _NUMBERS if k not in ("a", "an")) + r"|\d{1,2})\s+[a-z]",
                    re.IGNORECASE)


def _count(word: str) -> int:
    return int(word) if word.isdigit() else _NUMBERS[word.lower()]


def with_ordinal_others(text: str) -> str:
    """The text with each elliptic ordinal one more than a count said before it ("two guards ... and
    a third at X") said as "another"."""
    out = text
    for m in reversed(list(_ELLIPTIC.finditer(text))):
        before = [_count(c.group("n")) for c in _COUNT.finditer(text, 0, m.start())]
        if before and before[-1] + 1 == _ORDINALS[m.group("ord").lower()]:
            out = out[:m.start()] + f"{m.group('join')} another" + out[m.end():]
    return out
