"""One count said before two kinds of people joined by "and" (round 44): "twenty-two boys and girls",
"ten men and women", "a dozen mums and dads". The count is of both together: one group, as the
sentence says it ("The choir, twenty-two boys and girls in all, processes ..."), not the count's
kind and a second vague few of the other. Written before parsing as one plural that covers both
("twenty-two children", "ten people"). Two kinds each with a count of their own ("two nurses and three
doctors") or the second with a determiner ("ten kids and their parents") are two groups, untouched.
A quantifier that is not a number ("a handful of mums and dads", "a few lads and lasses", "several
nurses and porters") counts both the same way; and two kinds that pair off as the halves of one
people ("mums and dads", "boys and girls", "men and women") are one group with no count at all."""

from __future__ import annotations

import re

from grove_tui.language import lexicon as lx
from grove_tui.language.tokens import lemma

COUNT_WORD = r"(?:\d+|" + "|".join(sorted((w for w in lx.NUMBER_WORDS if w.isalpha() and w not in
                                        ("couple", "pair", "handful", "dozens", "one", "a")), key=len, reverse=True)) + \
    r")(?:-(?:one|two|three|four|five|six|seven|eight|nine))?"
_JOINED = re.compile(r"\b(" + COUNT_WORD + r")\s+([a-z][a-z-]+\s+)?([a-z][a-z-]+)\s+and\s+([a-z][a-z-]+)\b(?!\s*['’])",
                     re.IGNORECASE)  # one word that describes both may come first ("six adult sons and daughters")
_CHILDREN = frozenset("boy girl kid child toddler pupil schoolchild schoolboy schoolgirl son daughter infant "
                      "youngster teenager teen".split())

_GROWN = frozenset("adult grown grown-up grownup older elderly middle-aged".split())


def plural_person(word: str) -> bool:
    """Whether a word is a plural of people ("nurses", "staff"), no vague crowd word."""
    low = word.lower()
    base = lemma(low)
    if low in ("staff", "police", "crew"):
        return True  # "twelve staff and students"
    return base != low and (base in lx.PERSON_NOUNS or low in lx.PERSON_NOUNS) and base not in lx.IMPLIED_RANGES \
        and base not in lx.GENERIC_PEOPLE


def _joined(m: re.Match[str]) -> str:
    described, first, second = m.group(2) or "", m.group(3), m.group(4)
    if not (plural_person(first) and plural_person(second)) or first.lower() == second.lower():
        return m.group(0)
    if described and not _describes(described.strip()):
        return m.group(0)
    grown = described.strip().lower() in _GROWN  # "six adult sons and daughters": grown children, adults
    both = "children" if {lemma(first.lower()), lemma(second.lower())} <= _CHILDREN and not grown else "people"
    return f"{m.group(1)} {described}{both}"


def _describes(word: str) -> bool:
    """Whether a word before two joined kinds can describe both ("adult", "elderly", "grown-up",
    "excited"): no person, no number, no word of grammar ("and", "of")."""
    low = word.lower()
    return not plural_person(low) and low not in lx.NUMBER_WORDS and low not in lx.STOPWORDS and \
        low not in ("and", "or", "of", "plus")


_QUANTIFIER = r"(?:a\s+(?:handful|few|couple|group|bunch|crowd|gaggle|load|number|dozen\s+or\s+so)(?:\s+of)?|" \
    r"some|several|many|lots\s+of|loads\s+of|dozens\s+of|hundreds\s+of|plenty\s+of)"
_QUANTIFIED = re.compile(r"\b(" + _QUANTIFIER + r")\s+()([a-z][a-z-]+)\s+and\s+([a-z][a-z-]+)\b(?!\s*['’])",
                         re.IGNORECASE)
# Two kinds that are the halves of one people, said together as one ("mums and dads"): one group.
_HALVES = frozenset(frozenset(pair.split("/")) for pair in (
    "mum/dad mom/dad mother/father man/woman boy/girl lad/lass lad/girl guy/girl husband/wife brother/sister "
    "son/daughter grandma/grandpa grandmother/grandfather granny/grandad nan/grandad aunt/uncle niece/nephew "
    "grandson/granddaughter").split())
_PAIRED = re.compile(r"(?<![\w'’-])(?<!\band\s)([A-Za-z][a-z-]+)\s+and\s+([a-z][a-z-]+)\b(?!\s*['’])")


def _paired(m: re.Match[str]) -> str:
    first, second = m.group(1), m.group(2)
    if frozenset((lemma(first.lower()), lemma(second.lower()))) not in _HALVES or \
            not (plural_person(first) and plural_person(second)):
        return m.group(0)
    both = "children" if {lemma(first.lower()), lemma(second.lower())} <= _CHILDREN else "people"
    return both.capitalize() if first[0].isupper() else both


def with_joined_kinds(text: str) -> str:
    """The text with a count of two joined kinds of people written as one plural (module doc)."""
    return _PAIRED.sub(_paired, _QUANTIFIED.sub(_joined, _JOINED.sub(_joined, text)))
