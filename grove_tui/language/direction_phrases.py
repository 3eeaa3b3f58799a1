"""Directions written as a phrase: "in the direction of the café", "in the general direction of the
exit", "in the café's direction" name where someone is heading exactly as "towards the café" does.

The reader's route passes know "towards" (a destination, refused when the world lacks the place); the
long phrase left the place unread, or read "direction" as a noun with the place hanging off "of". The
phrase is rewritten to "towards <place>" before parsing, so every pass sees one way of saying it.
"""

from __future__ import annotations

import re

# "in the (general|rough|same) direction of X" -> "towards X"
_DIRECTION_OF = re.compile(r"\b(?:in|into)\s+(?:the\s+)?(?:(?:general|rough|vague|approximate)\s+)?"
                           r"directions?\s+of\b", re.IGNORECASE)
# "in the café's direction", "in the main hall's general direction" -> "towards the café"
_OWNED_DIRECTION = re.compile(r"\bin\s+((?:the|a|an)\s+(?:[\w-]+\s+){0,3}?[\w-]+)['’]s?\s+"
                              r"(?:(?:general|rough|vague|approximate)\s+)?direction\b", re.IGNORECASE)


def towards_for_direction(text: str) -> str:
    """The text with each direction phrase said as "towards"."""
    text = _DIRECTION_OF.sub("towards", text)
    return _OWNED_DIRECTION.sub(lambda m: f"towards {m.group(1)}", text)
