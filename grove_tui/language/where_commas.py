"""A comma before a "where" clause that counts people at a place (probe round r64c): "the robot brings
coffee to the boardroom where eight people are in a meeting". Without the comma the parser reads the
counted people as part of the place phrase and the group is lost; with it ("the boardroom, where eight
people are ...") they are a group of the scene at that place. Only a "where" right after a noun phrase
begun by a determiner, and followed at once by a count, is given the comma; "runs to where the staff
are" and "the room where staff sit" keep their own reading (where_people.py)."""

from __future__ import annotations

import re

from grove_tui.language.lexicon import NUMBER_WORDS

_COUNTS = sorted(NUMBER_WORDS | {"several", "many", "dozens"}, key=len, reverse=True)
# "the food court where 30 people", "a quiet room where a dozen nurses": a determiner, up to three more
# words of the place's name, then "where" and a count.
_WHERE_COUNT = re.compile(
    r"\b((?:the|a|an)\s+(?:[A-Za-z0-9'-]+\s+){0,3}[A-Za-z0-9'-]+)\s+where\s+"
    r"(?=(?:a\s+|about\s+|some\s+|around\s+)?(?:\d+|" + "|".join(_COUNTS) + r")\b)",
    re.IGNORECASE)


def where_commas(text: str) -> str:
    """The text with a comma before each "where" that counts people after a place noun phrase."""
    return _WHERE_COUNT.sub(lambda m: f"{m.group(1)}, where ", text)
