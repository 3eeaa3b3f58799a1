"""One count said before a list of kinds of people ("twenty-odd mums, partners and grandparents", "the
twenty or so owners and staff", "about thirty nurses, porters, and cleaners") counts them all: one
group, as "ten men and women" is (language/joined_kinds.py, which this extends to lists of three or
more, and to counts said roughly: "-odd", "or so", "and more"). Written before parsing as one
plural that covers them all ("twenty-odd people"). A kind with a count or determiner of its own
("ten nurses, two porters and a cleaner") ends the list there and is untouched."""

from __future__ import annotations

import re

from grove_tui.language import lexicon as lx
from grove_tui.language.tokens import lemma

_NUMBER = r"(?:\d+|" + "|".join(sorted((w for w in lx.NUMBER_WORDS if w.isalpha() and w not in
                                        ("couple", "pair", "handful", "dozens", "one", "a")), key=len, reverse=True)) + \
    r")(?:-(?:one|two|three|four|five|six|seven|eight|nine))?"
_ROUGHLY = r"(?:-odd|\s+odd|\s+or\s+so)?"
_KIND = r"[a-z][a-z-]+"
# A count, then kinds "A, B and C" (or "A and B" after a rough count): each kind one word.
_LISTED = re.compile(r"\b(" + _NUMBER + _ROUGHLY + r")\s+(" + _KIND + r"(?:\s*,\s*" + _KIND + r")*"
                     r"(?:\s*,)?\s+and\s+" + _KIND + r")\b(?!\s*['’])", re.IGNORECASE)
_SPLIT = re.compile(r"\s*,\s*(?:and\s+)?|\s+and\s+", re.IGNORECASE)


def _plural_person(word: str) -> bool:
    low = word.lower()
    base = lemma(low)
    if low in ("staff", "police", "crew"):
        return True  # "twenty or so owners and staff"
    return base != low and (base in lx.PERSON_NOUNS or low in lx.PERSON_NOUNS) and base not in lx.IMPLIED_RANGES \
        and base not in lx.GENERIC_PEOPLE


def _listed(m: re.Match[str]) -> str:
    count, kinds = m.group(1), [k for k in _SPLIT.split(m.group(2)) if k]
    rough = count.lower() != re.sub(_ROUGHLY + "$", "", count.lower())
    if len(kinds) < (2 if rough else 3) or not all(_plural_person(k) for k in kinds):
        return m.group(0)  # two kinds under a plain count: joined_kinds' own rule
    if len({k.lower() for k in kinds}) < len(kinds):
        return m.group(0)
    return f"{count} people"


def with_counted_lists(text: str) -> str:
    """The text with a count before a list of kinds of people written as one plural (module doc)."""
    return _LISTED.sub(_listed, text)
