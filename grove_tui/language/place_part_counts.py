"""A part of a place said with a count or "either" (round 40): "along one side of the table in huddle room
two", "at one end of the café counter", "on either side of the bar", "at both ends of the tables", "at the
head of the table". A part of a place is the place ("the far end of the counter" already is); these say
the part with a word the reader took for a count, so they are said again as "the side of", "the end of"."""

from __future__ import annotations

import re

_PARTS = r"(?:side|sides|end|ends|corner|corners|edge|edges)"
_COUNTED = re.compile(r"\b(?:one|either|each|both|one\s+of\s+the)\s+(" + _PARTS + r")\s+of\s+(?=(?:the|a|an|his|her|their|its|our)\b)",
                      re.I)
# "the head of the table": the end a table has, not the head of a department ("the head of security").
_HEAD = re.compile(r"\b(the)\s+(?:head|top|foot)\s+of\s+(?=(?:the|a)\s+(?:[\w'-]+\s+){0,3}?(?:table|tables|bed|beds)\b)", re.I)


def with_plain_parts(text: str) -> str:
    """The text with a counted part of a place said as "the <part> of"."""
    text = _COUNTED.sub(lambda m: "the " + m.group(1).lower().rstrip("s") + " of ", text)
    return _HEAD.sub(lambda m: m.group(1) + " end of ", text)
