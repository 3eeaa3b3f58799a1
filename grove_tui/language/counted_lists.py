"""One count said before a list of kinds of people ("twenty-odd mums, partners and grandparents", "the
twenty or so owners and staff", "about thirty nurses, porters, and cleaners") counts them all: one
group, as "ten men and women" is (language/joined_kinds.py, which this extends to lists of three or
more, and to counts said roughly: "-odd", "or so", "and more"). Written before parsing as one
plural that covers them all ("twenty-odd people"). A kind with a count or determiner of its own
("ten nurses, two porters and a cleaner") ends the list there and is untouched."""

from __future__ import annotations

import re

from grove_tui.language.joined_kinds import COUNT_WORD, plural_person

_ROUGHLY = r"(?:-odd|\s+odd|\s+or\s+so)?"
_KIND = r"[a-z][a-z-]+"
# A count, then kinds "A, B and C" (or "A and B" after a rough count): each kind one word.
_LISTED = re.compile(r"\b(" + COUNT_WORD + _ROUGHLY + r")\s+(" + _KIND + r"(?:\s*,\s*" + _KIND + r")*"
                     r"(?:\s*,)?\s+and\s+" + _KIND + r")\b(?!\s*['’])", re.IGNORECASE)
_SPLIT = re.compile(r"\s*,\s*(?:and\s+)?|\s+and\s+", re.IGNORECASE)


def _listed(m: re.Match[str]) -> str:
    count, kinds = m.group(1), [k for k in _SPLIT.split(m.group(2)) if k]
    rough = count.lower() != re.sub(_ROUGHLY + "$", "", count.lower())
    if len(kinds) < (2 if rough else 3) or not all(plural_person(k) for k in kinds):
        return m.group(0)  # two kinds under a plain count: joined_kinds' own rule
    if len({k.lower() for k in kinds}) < len(kinds):
        return m.group(0)
    return f"{count} people"


def with_counted_lists(text: str) -> str:
    """The text with a count before a list of kinds of people written as one plural (module doc)."""
    return _LISTED.sub(_listed, text)
