"""The second of two people joined by "and" with no verb, then where they are (round 58): "Mum and Dad
at the kitchen table, the kids in the lounge", "Nan and Grandad in the garden". The first person counts
as a subject because another person follows its "and" (language/people_phrases.py); the second had no
verb after it and was dropped, so a couple of two was read as one person. A singular person word right
after "<person> and", the pair opening its clause, and a place preposition after it, is a person too
(the two are then one couple: language/couples.py)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from grove_tui.language import lexicon as lx

if TYPE_CHECKING:
    from grove_tui.language.people import People
    from grove_tui.language.sentence import Sentence

_DETERMINERS = frozenset({"the", "a", "an", "my", "our", "his", "her", "their", "your"})


def second_of_a_placed_pair(s: Sentence, people: People, head: int) -> bool:
    """Whether person word `head` is "<person> and <head> <place preposition>" opening a clause."""
    if head < 2 or head + 1 >= s.n or s.low[head - 1] != "and" or s.low[head + 1] not in lx.PLACE_PREPOSITIONS:
        return False
    if s.low[head + 1] in ("of", "to", "from") or not people.is_person_noun(head - 2):
        return False
    start = head - 2
    while start > 0 and s.low[start - 1] in _DETERMINERS:
        start -= 1
    return start == 0 or s.is_punct(start - 1) or s.low[start - 1] in lx.CLAUSE_STARTERS
