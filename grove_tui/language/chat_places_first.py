"""Chat items that say the place first and count its people in brackets after: "dorm 1 still asleep
(3 ppl)", "lobby heaving (10 people)". The item is written out as its people in that place ("3 people
in dorm 1 still asleep"), so that the count is a group and the place where it is, as when typed that way.
An item that starts with people ("the cyclists (3 people)"), says a preposition of its own ("queue at
till (5 ppl)") or goes on after the bracket ("the school group (25 children) walks") is left alone.
A place said crowded ("busy", "heaving", "packed") takes a bare figure too: "concourse busy (about 30)"
is about 30 people there, since a crowd is what the word counts.
"""

from __future__ import annotations

import re

from grove_tui.language.bracketed_counts import _is_count_of_people as is_count_of_people
from grove_tui.language.lexicon import PERSON_NOUNS
from grove_tui.language.tokens import lemma

# An item: at the start or after a comma, semicolon or colon; some plain words; a bracket; then the item's end.
_ITEM = re.compile(r"(?:^|(?<=[,;:]))(\s*)([A-Za-z][A-Za-z0-9' -]{1,40}?)\s*\(\s*([^()]{1,30}?)\s*\)"
                   r"(?=\s*(?:[,;.!]|$))")
# Words that put a place of its own in the item, or make it a sentence rather than a place and its state.
_NOT_BARE = frozenset("in at on by to from into near inside outside with is are was were has have".split())
# Words that say a place holds a crowd: a bare figure in brackets after them counts its people.
_CROWDED = frozenset("busy busier heaving packed rammed crowded full mobbed jammed swarming teeming bustling "
                     "thronged chocka chockablock".split())
# A bare figure: a number, said roughly or not ("about 30", "30", "at least 20", "30 or so").
_FIGURE = re.compile(r"^(?:(?:about|around|roughly|approx\.?|approximately|some|maybe|nearly|almost|c\.|ca\.|"
                     r"at\s+least|over|under)\s+)?\d{1,4}(?:\s+or\s+so)?$", re.IGNORECASE)


def places_first(text: str) -> str:
    """The text with each chat item "<place> <state> (<count of people>)" as "<count> in <place> <state>"."""
    return _ITEM.sub(_rewritten, text)


def _rewritten(m: re.Match[str]) -> str:
    lead, item, inside = m.group(1), m.group(2).strip(), m.group(3)
    words = item.lower().split()
    if words and words[-1] in _CROWDED and _FIGURE.match(inside.strip()):
        inside = f"{inside.strip()} people"
    if not is_count_of_people(inside) or not 1 <= len(words) <= 6 or set(words) & _NOT_BARE or \
            any(lemma(w) in PERSON_NOUNS or w in ("people", "ppl", "persons") for w in words):
        return m.group(0)
    return f"{lead}{inside} in {item}"
