"""A person moved by someone of theirs, said with a pronoun (round 33): "Mr Ahmed's son wheels him from
reception to the bars", "her daughter pushes her in to the lounge", "his carer wheels him back to the
ward". The pronoun after a verb that takes someone along a route is the person whose son, daughter or
carer the subject is: a second group that goes along, as "wheels his father from ..." is."""

from __future__ import annotations

from grove_tui.language.caused_motion import taking_verb
from grove_tui.language.sentence import Sentence

# Words that start the way someone is taken ("from", "back to", "in to", "over to", "out of").
_ROUTE = frozenset("from to into onto out back over in across through down up along round around towards toward "
                   "off away home inside outside".split())
# The pronoun and the possessives that say whose the subject is ("his carer ... him").
_OWN = {"him": frozenset({"his", "'s", "’s"}), "her": frozenset({"her", "'s", "’s"})}
_CLAUSE_BREAKS = frozenset({",", ";", ".", "and", "while", "as", "when", "then", "but"})


def moved_pronoun(s: Sentence, at: int) -> bool:
    """Whether the word at `at` is "him" or "her", the object of a person's verb that takes it along a
    route, said of someone whose son, carer or daughter the subject of that verb is."""
    owners = _OWN.get(s.low[at])
    if owners is None or at < 2 or at + 1 >= s.n or not taking_verb(s, at - 1):
        return False
    nxt = s.low[at + 1]
    if nxt not in _ROUTE or s.w[at + 1].pos in ("NOUN", "PROPN", "ADJ"):
        return False  # "pushes her pram": her own thing, no one moved
    j = at - 2
    while j >= 0 and s.low[j] not in _CLAUSE_BREAKS and s.w[j].sentence == s.w[at].sentence:
        if s.low[j] in owners:  # "Mr Ahmed's son", "his carer": the one whose the subject is, said first
            return s.low[j] in ("'s", "’s") or j == 0 or s.is_punct(j - 1) or s.w[j - 1].sentence != s.w[j].sentence
        j -= 1
    return False


def owner_name(s: Sentence, at: int) -> str:
    """How the moved person is called: the name before "'s" in the subject ("Mr Ahmed"), else the pronoun."""
    j = at - 2
    while j > 0 and s.low[j] not in _CLAUSE_BREAKS:
        if s.low[j] in ("'s", "’s"):
            k = j
            while k > 0 and s.w[k - 1].pos == "PROPN" and s.w[k - 1].text[:1].isupper():
                k -= 1
            return s.span(k, j - 1) if k < j else s.w[at].text
        j -= 1
    return s.w[at].text

