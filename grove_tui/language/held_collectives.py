"""Collective nouns that are also things one holds: "golf clubs", "rucksack packs". "Six beginners with
hired clubs", "two golfers carry their clubs": the plural after "with", a possessive or a verb (past
any adjectives: "hired", "borrowed") is what they hold, not a second group of a club's members. A
club of people is said with an article or a count ("the golf club meets", "two clubs of ramblers")."""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from grove_tui.language.sentence import Sentence

# Collectives whose plural is as often a thing carried.
_HELD = frozenset({"club", "pack"})
_HOLDERS = frozenset({"with", "their", "his", "her", "my", "our", "your", "its"})


def held_not_people(s: Sentence, head: int) -> bool:
    """Whether the collective at `head` is a plural held thing ("with hired clubs", "their clubs")."""
    if s.lemma(head) not in _HELD or s.low[head] == s.lemma(head) or \
            (head + 1 < s.n and s.low[head + 1] == "of"):
        return False  # "a club", "packs of teenagers": people
    j = head - 1
    while j >= 0 and (s.w[j].pos == "ADJ" or s.w[j].tag == "VBN"):
        j -= 1  # "with hired clubs", "their heavy packs"
    return j >= 0 and (s.low[j] in _HOLDERS or s.w[j].pos == "VERB")
