"""Two people typed as chat with "+" or "&" as an item of a list (round 32): "pt in chair 2, nurse +
dentist w/ her, 3 waiting in reception", "guard + cleaner by the fountain, 3 teens at the food court".
Each is a person of their own, but two bare role nouns joined by a sign (written "and" by `text.py`) read
as one noun ("nurse"), and the second person was lost. Only two bare singular people are written out;
plurals ("nurses and porters") already read as two groups. Written out ("a nurse and a dentist"), they are one group each, as when the
sentence says so in words."""

from __future__ import annotations

import re

from grove_tui.language import lexicon as lx
from grove_tui.language.tokens import lemma

# The signs are "and" by now (text.py): "nurse and dentist" as a chat item, no article to either.
# Not before an "-ing" verb: "pilot n steward walking to gate a1" reads as two people already.
_PAIR = re.compile(r"(^|[,;:]\s*)([a-z]+)\s+and\s+([a-z]+)\b(?!\s+and\b)(?!\s+[a-z]+ing\b)")


# Kin and partners said bare ("bf n gf", "mum and dad") already read as one person each: left alone.
_KIN = frozenset("boyfriend girlfriend husband wife partner fiance fiancee spouse mum mom dad mother father son "
                 "daughter brother sister gran granny grandad grandma grandpa nan nana aunt uncle cousin niece "
                 "nephew baby toddler kid child grandson granddaughter".split())


def _person(word: str) -> bool:
    return word in lx.PERSON_NOUNS or lemma(word) in lx.PERSON_NOUNS


def _one(word: str) -> str:
    return ("an " if word[0] in "aeiou" else "a ") + word


def with_chat_pairs(text: str) -> str:
    """The text with two bare people joined by "+" or "&" written as two people (module doc)."""
    def said(m: re.Match[str]) -> str:
        first, second = m.group(2), m.group(3)
        if not (_person(first) and _person(second)) or lemma(first) != first or lemma(second) != second \
                or first in _KIN or second in _KIN:
            return m.group(0)
        return f"{m.group(1)}{_one(first)} and {_one(second)}"
    return _PAIR.sub(said, text)
