"""Events said as the cause of people leaving (round 19): "so the toy store shuts and the shoppers
hurry out", "someone has left a bag by the fountain, so the atrium is cleared: 60 shoppers are sent
out". A place that shuts is no person, and whoever left the thing that caused the clearing is no
group that moves: the people who leave are the group, from the zone that is shut or cleared."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import replace

from grove_tui.language import lexicon as lx
from grove_tui.language.mention import Mention
from grove_tui.language.parser import Word
from grove_tui.language.sentence import Sentence

# Verbs of a place shutting, in the forms the small parser takes for nouns after a noun
# ("the toy store shuts", "the café closes and ...").
_SHUTTING = frozenset({"shuts", "closes", "shut", "closed"})
# What may follow a place's shutting verb: the end of its clause.
_AFTER_SHUTTING = frozenset({"", ".", "!", ",", ";", ":", "and", "so", "down", "early", "suddenly", "immediately"})


def shutting_verbs(words: list[Word]) -> list[Word]:
    """The parse with a place's shutting verb the parser took for a noun tagged as a verb."""
    out = list(words)
    for k, w in enumerate(words):
        nxt = words[k + 1].lower if k + 1 < len(words) else ""
        if w.lower in _SHUTTING and w.pos != "VERB" and nxt in _AFTER_SHUTTING and k > 0 and \
                words[k - 1].pos in ("NOUN", "PROPN"):
            out[k] = replace(w, pos="VERB", tag="VBZ" if w.lower.endswith("s") else "VBD", dep="ROOT", head=k)
            prev = out[k - 1]
            if prev.dep == "compound" and prev.head == k:
                out[k - 1] = replace(prev, dep="nsubj", head=k)
    return out


# Verbs of leaving a thing behind that causes a clearing ("someone has left a rucksack under the board").
_LEAVING_A_THING = frozenset(f"{v}{end}" for v in ("abandon", "dump") for end in ("", "s", "ed", "ing")) | \
    frozenset("leave leaves left leaving forget forgets forgot forgotten drop drops dropped".split())
# Verbs of a zone being cleared or shut because of it ("so the hall is cleared", "the shop closes").
_CLEARING = frozenset(f"{v}{end}" for v in ("clear", "empty", "evacuate", "vacate", "close", "cordon", "seal")
                      for end in ("", "s", "d", "ed", "ing")) | frozenset("shut shuts emptied empties".split())
_AUX = frozenset("has have had 's ’s just is was".split())


def _leaves_at(s: Sentence, v: int) -> bool:
    return v < s.n and s.low[v] in _LEAVING_A_THING


def left_thing(s: Sentence, v: int) -> bool:
    """Whether the verb at v leaves a thing behind: "left a rucksack", "abandons a bag" (one leaves
    "the café", never "a café"), so its object is no place to refuse."""
    return _leaves_at(s, v) and v + 1 < s.n and s.low[v + 1] in ("a", "an")


def _causer(s: Sentence, m: Mention) -> bool:
    """Whether m only leaves a thing behind, and a zone is then cleared for it (see the module doc)."""
    v = s.skip(m.last + 1, _AUX)
    if not _leaves_at(s, v) or v + 1 >= s.n:
        return False
    obj = v + 1
    while obj < s.n and s.w[obj].pos in ("DET", "ADJ", "NUM"):
        obj += 1
    if obj >= s.n or s.w[obj].pos not in ("NOUN", "PROPN") or s.lemma(obj) in lx.PERSON_NOUNS or \
            s.index.knows(s.lemma(obj)):
        return False  # "leaves the café", "leaves his son": leaving a place, or a person
    return any(s.low[k] in _CLEARING and s.w[k].pos == "VERB" for k in range(obj + 1, s.n))


def without_causers(s: Sentence, mentions: Sequence[Mention]) -> list[Mention]:
    """The mentions but whoever only left behind the thing a zone is cleared for."""
    if len(mentions) < 2:
        return list(mentions)
    kept = [m for m in mentions if not _causer(s, m)]
    if not kept or any(m.relation is not None for m in mentions):
        return list(mentions)
    return kept
