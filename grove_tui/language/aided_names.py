"""A person by bare name helped along by someone (round 38): "a carer steadies Stan on his frame as he
shuffles from the dining room to the piano", "a nurse helps Doris, with her stick, while she totters
over to the garden". The name after a verb of taking or helping is a person when what follows is what
they lean on, then "as"/"while" and "he"/"she" with a verb, then a route: the route is theirs, walked
with their helper (the caller checks the subject is a person)."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.caused_motion import ROUTE_WORDS
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import verb_lemma

# What someone leans on as they go ("on his frame", "with her stick", "on crutches").
_AIDS = frozenset("frame walker zimmer stick cane crutch crutches rollator arm arms elbow hand".split())
_OWNERS = frozenset("his her their a an the two both".split())
_TIMES = frozenset({"as", "while", "whilst", "when"})
_PRONOUNS = frozenset({"he", "she", "they"})


def aided_name(s: Sentence, i: int) -> bool:
    """Whether word i is a bare given name a verb of taking or helping right before takes along the
    route the clause after "as he ..." walks ("steadies Stan on his frame as he shuffles from ...")."""
    w = s.w[i]
    if w.pos != "PROPN" or i < 2 or not w.text[:1].isupper() or not s.low[i].isalpha() or \
            s.low[i] in lx.ROBOT_WORDS or verb_lemma(s.low[i - 1]) not in lx.LEADING_VERBS:
        return False
    k = i + 1
    if k < s.n and s.low[k] == ",":
        k += 1
    if k + 1 < s.n and s.low[k] in ("on", "with", "by"):
        j = k + 1
        while j < s.n and (s.low[j] in _OWNERS or s.w[j].pos == "ADJ"):
            j += 1
        if j >= s.n or s.lemma(j) not in _AIDS and s.low[j] not in _AIDS:
            return False
        k = j + 1
        if k < s.n and s.low[k] == ",":
            k += 1
    if k + 2 >= s.n or s.low[k] not in _TIMES or s.low[k + 1] not in _PRONOUNS:
        return False
    j = k + 2
    while j < s.n and s.w[j].pos == "ADV":
        j += 1
    if j >= s.n or s.w[j].pos != "VERB":
        return False
    j += 1
    while j < s.n and (s.w[j].pos == "ADV" or s.low[j] in ("slowly", "along", "off")) and s.low[j] not in ROUTE_WORDS:
        j += 1
    return j + 1 < s.n and s.low[j] in ROUTE_WORDS
