"""A count of people in brackets after a group and before its verb ("The school group (25 children)
walks to the hall", "Year 3 (28 pupils) ..."): the same apposition as with commas, so it is written
with commas before parsing and the group is the counted people (apposed_counts.py), not a second
group beside an implied one."""

from __future__ import annotations

import re

from grove_tui.language.lexicon import PERSON_NOUNS, TENS, UNITS
from grove_tui.language.tokens import lemma

# Brackets between a word and a word: what a bracket after the verb or at the end holds is left alone.
_BRACKET = re.compile(r"(?<=[A-Za-z0-9])\s*\(\s*([^()]{1,48}?)\s*\)\s*(?=[A-Za-z])")
_APPROXIMATE = frozenset("about around roughly approximately approx some maybe nearly almost c. ca.".split())


def _is_count_of_people(inside: str) -> bool:
    """ "25 children", "about 40 guests", "twenty pupils": a number, then people by a person noun."""
    words = inside.lower().replace("-", " ").split()
    while words and words[0] in _APPROXIMATE:
        words = words[1:]
    if len(words) < 2 or not (words[0].isdigit() or words[0] in UNITS or words[0] in TENS):
        return False
    noun = words[-1].strip(".,")
    return len(words) <= 4 and (noun in ("people", "persons") or lemma(noun) in PERSON_NOUNS)


def commas_for_brackets(text: str) -> str:
    """The text with a bracketed count of people in apposition set off by commas instead."""
    return _BRACKET.sub(lambda m: f", {m.group(1)}, " if _is_count_of_people(m.group(1)) else m.group(0), text)
