"""A year of study before the words naming the students (round 32): "six third-year medical students",
"a final-year law student", "four first-year nursing students". "third-year" alone is a student of
that year ("two third-years wait"), but before a describing word and a person noun it only says
which year they are in: one group, the person noun its head, not a second person."""

from __future__ import annotations

import re

from grove_tui.language.lexicon import PERSON_NOUNS
from grove_tui.language.tokens import lemma

# The words after the year, up to the person noun: "medical students", "art history students".
_NEXT_WORDS = re.compile(r"\s+([A-Za-z]+(?:-[A-Za-z]+)?)(?:\s+([A-Za-z]+(?:-[A-Za-z]+)?))?(?:\s+([A-Za-z]+))?")
# Words that end a noun phrase before its person noun could come: a verb or a preposition.
_STOPS = frozenset("and or with in at on to from by of is are was were who that walk walks wait waits".split())


def year_of_people(text: str, end: int) -> bool:
    """Whether the year of study ending at `end` describes a person noun one to three words on."""
    m = _NEXT_WORDS.match(text, end)
    if m is None:
        return False
    words = [w for w in m.groups() if w]
    for k, word in enumerate(words):
        low = word.lower()
        if low in _STOPS:
            return False
        if k > 0 and (low in PERSON_NOUNS or lemma(low) in PERSON_NOUNS):
            return True
    return False
