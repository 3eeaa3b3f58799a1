"""A held thing fronted before the subject (round 48): "Mug in hand, a keeper walks to ...", "Flask under
one arm, two porters ...", "Travel cup in her hand, a commuter ...". The parser takes the capitalised first
word for a name and the subject of the clause, so a person called "Mug" was read. The phrase says what
the subject carries, not who is there: its first word is written small for the parser, as a fronted
feeling is (fronted_feelings.py), and the held thing is left to the rules of held things (held_and_spans.py)."""

from __future__ import annotations

import re

_BODY = r"(?:hands?|arms?|fists?|palms?|shoulders?|hips?|lap|teeth|mouth|grip|grasp)"
_FRONTED_HELD = re.compile(r"^([A-Z][a-z]+)((?:\s+[a-z]+){0,2}\s+(?:in|on|under|over|between)\s+"
                           r"(?:(?:his|her|their|my|one|each|both|either|the|a|left|right|free|other)\s+){0,2}"
                           + _BODY + r"\s*,\s+)")
_SUBJECT_STARTS = frozenset("a an the two three four five six seven eight nine ten some several his her their "
                            "our my this that these those one".split())


def with_small_held_fronts(text: str) -> str:
    """The text with a fronted held thing's first word written small (module doc)."""
    m = _FRONTED_HELD.match(text)
    if m is None:
        return text
    rest = text[m.end():]
    first = rest.split(" ", 1)[0].lower() if rest else ""
    if first not in _SUBJECT_STARTS and not first[:1].isdigit():
        return text
    return m.group(1).lower() + text[m.end(1):]
