"""Things named after the people they are for, with a hyphenated modifier of person words (round 44):
"before the parent-and-baby session", "the parent-and-child swim",
"the adults-only sauna". The person words inside name who the session or room is for, not anyone there:
"the parent" became a group of one, "toddler class" a class of children. The modifier is left out before
the sentence is parsed ("before the session"); the thing it named is still read."""

from __future__ import annotations

import re
from functools import lru_cache
from typing import TYPE_CHECKING

from grove_tui.language import lexicon as lx
from grove_tui.language.tokens import lemma

if TYPE_CHECKING:
    from grove_tui.language.places import PlaceIndex

# "parent-and-baby", "mum-and-toddler", "parent-n-child", "adults-only", "kids-only"
_MODIFIER = re.compile(r"\b(?:the|a|an|their|our|this|that)\s+(([A-Za-z]+)\s*-\s*(?:and|n|'n'|&)\s*-\s*"
                       r"([A-Za-z]+)|([A-Za-z]+)\s*-\s*only)\s+([a-z]+)\b", re.IGNORECASE)


# Collectives that are events too, said after a word of time ("before the parent-and-baby class").
_EVENT_COLLECTIVES = frozenset({"class", "group", "club"})
_TIME_WORDS = frozenset({"before", "after", "until", "till", "for", "during"})


def _person(word: str | None) -> bool:
    if not word:
        return False
    low = word.lower()
    return low in lx.PERSON_NOUNS or lemma(low) in lx.PERSON_NOUNS


@lru_cache(maxsize=32)
def _names(index: PlaceIndex) -> frozenset[str]:
    return frozenset(" ".join(said.lower().replace("-", " ").split()) for e in index.entries for said in e.said)


def _without(m: re.Match[str], index: PlaceIndex) -> str:
    first, second, only, thing = m.group(2), m.group(3), m.group(4), m.group(5)
    said = " ".join(f"{m.group(1)} {thing}".lower().replace("-", " ").replace("'n'", "and").split())
    if said in _names(index) or said.replace(" n ", " and ") in _names(index):
        return m.group(0)  # "the mother-and-baby ward" of a maternity unit: a place's own name
    if only is not None:
        people = _person(only)
    else:
        people = _person(first) and _person(second)
    before = m.string[:m.start()].split()[-1:]
    event = thing.lower() in _EVENT_COLLECTIVES and before and before[0].lower() in _TIME_WORDS
    if not people or (_person(thing) or lemma(thing.lower()) in lx.IMPLIED_RANGES) and not event:
        return m.group(0)  # "the mother-and-toddler pairs", "the parent-and-baby group meets": people after all
    return m.group(0).replace(m.group(1) + " ", "", 1)


def without_people_named_things(text: str, index: PlaceIndex) -> str:
    """The text with person words that only name what a thing is for left out (module doc); a name of
    the world's own ("the mother-and-baby ward") is kept."""
    return _MODIFIER.sub(lambda m: _without(m, index), text)
