"""A place kept away from, said by a participle (probe round r64c): "the robot goes to the server room,
keeping away from the kitchen", "staying well clear of the lobby". The bare "from" made the place the
mover's start; the phrase says a place not to use, as "avoiding the kitchen" does, and is read so.
Only a place: "keeping away from the robot" (or "it", "them") is a reaction and is left alone."""

from __future__ import annotations

import re

_KEPT_AWAY = re.compile(
    r"\b(?:keeping|staying|steering|keep|stay)\s+(?:well\s+|right\s+)?(?:away\s+from|clear\s+of)\s+"
    r"(?=(?:the|a|an|any)\s+(?!robot\b|robots\b|machine\b|bot\b))",
    re.IGNORECASE)


def kept_away(text: str) -> str:
    """The text with "keeping away from the X" said as "avoiding the X" for a place X."""
    return _KEPT_AWAY.sub("avoiding ", text)
