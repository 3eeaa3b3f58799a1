"""A person moved in their own chair by someone of theirs (round 38): "Grace's son steers her chair
from the salon to the nurses' station", "Mr Ahmed's daughter pushes his wheelchair back to the
ward", "his carer wheels his bed down to X-ray". The possessive before the thing is the person whose
son, daughter or carer the subject is, as "wheels him from ..." is (moved_pronouns.py): a second
group, in the thing, that goes along. A pram or buggy is a child's, not its pusher's kin, so it is
left to the readings of carried things."""

from __future__ import annotations

from grove_tui.language.caused_motion import taking_verb
from grove_tui.language.moved_pronouns import owner_name
from grove_tui.language.sentence import Sentence

# What a grown person is moved in ("her chair", "his wheelchair", "her bed").
_RIDES = frozenset("wheelchair chair bed stretcher gurney".split())
_ROUTE = frozenset("from to into onto out back over in across through down up along round around towards toward "
                   "off away home inside outside".split())
# The possessive and the words that say whose the subject is ("his carer ... his chair", "Grace's son ... her").
_OWN = {"his": frozenset({"his", "'s", "’s"}), "her": frozenset({"her", "'s", "’s"})}
_CLAUSE_BREAKS = frozenset({",", ";", ".", "and", "while", "as", "when", "then", "but"})


def own_ride(s: Sentence, at: int) -> int | None:
    """The index of the chair when the word at `at` is "his"/"her" before a chair a person's verb right
    before takes along a route ("Grace's son steers her chair from ..."), said of someone whose son,
    daughter or carer the subject is; else None."""
    owners = _OWN.get(s.low[at])
    if owners is None or at < 2 or not taking_verb(s, at - 1):
        return None
    thing = at + 1
    while thing < s.n and s.w[thing].pos == "ADJ" and s.lemma(thing) not in _RIDES:
        thing += 1
    if thing + 1 >= s.n or s.lemma(thing) not in _RIDES or s.low[thing + 1] not in _ROUTE:
        return None
    j = at - 2
    while j >= 0 and s.low[j] not in _CLAUSE_BREAKS and s.w[j].sentence == s.w[at].sentence:
        if s.low[j] in owners:
            first = j == 0 or s.is_punct(j - 1) or s.w[j - 1].sentence != s.w[j].sentence
            return thing if s.low[j] in ("'s", "’s") or first else None
        j -= 1
    return None


def ride_owner_name(s: Sentence, at: int) -> str:
    """How the person in the chair is called: the name before "'s" in the subject, else "her"/"him"."""
    name = owner_name(s, at)
    if name == s.w[at].text:
        return {"his": "him", "her": "her"}.get(s.low[at], name)
    return name
