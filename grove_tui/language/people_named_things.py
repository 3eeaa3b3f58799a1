"""Things named after the people they are for, with a hyphenated modifier of person words (round 44):
"before the parent-and-baby session", "the parent-and-child swim",
"the adults-only sauna". The person words inside name who the session or room is for, not anyone there:
"the parent" became a group of one, "toddler class" a class of children. The modifier is left out before
the sentence is parsed ("before the session"); the thing it named is still read."""

from __future__ import annotations

import re

from grove_tui.language import lexicon as lx
from grove_tui.language.tokens import lemma

# "parent-and-baby", "mum-and-toddler", "parent-n-child", "adults-only", "kids-only"
_MODIFIER = re.compile(r"\b(?:the|a|an|their|our|this|that)\s+(([A-Za-z]+)\s*-\s*(?:and|n|'n'|&)\s*-\s*"
                       r"([A-Za-z]+)|([A-Za-z]+)\s*-\s*only)\s+([a-z]+)\b", re.IGNORECASE)


def _person(word: str | None) -> bool:
    if not word:
        return False
    low = word.lower()
    return low in lx.PERSON_NOUNS or lemma(low) in lx.PERSON_NOUNS


def _without(m: re.Match[str]) -> str:
    first, second, only, thing = m.group(2), m.group(3), m.group(4), m.group(5)
    if only is not None:
        people = _person(only)
    else:
        people = _person(first) and _person(second)
    if not people or _person(thing) or lemma(thing.lower()) in lx.IMPLIED_RANGES:
        return m.group(0)  # "the mother-and-toddler pairs", "the parent-and-baby group": people after all
    return m.group(0).replace(m.group(1) + " ", "", 1)


def without_people_named_things(text: str) -> str:
    """The text with person words that only name what a thing is for left out (module doc)."""
    return _MODIFIER.sub(_without, text)
