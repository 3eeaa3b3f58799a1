"""What people hide behind or under (round 52): "ducks behind the curtains", "hides under the duvet",
"cowers behind a pot plant", "crouches beneath the desk". After a verb of hiding or of a quick, low
move, "behind"/"under" names a thing one shelters by, not a room: when the world has no such thing and
the phrase's head is no word for a room, there is nothing to refuse. A thing the world has is still
read as a place ("behind the sofa" where the lounge has a sofa); a room the world lacks ("hides in the
attic", "behind the boiler room") is still refused."""

from __future__ import annotations

from grove_tui.language.hazards import ROOM_HEADS
from grove_tui.language.hiding_moves import hides_by_moving
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import lemma, verb_lemma

_BEHIND = frozenset("behind under underneath beneath".split())
# Verbs of hiding or sheltering that need no quick move ("hides behind", "cowers under", "peeps from behind").
_HIDING = frozenset("hide cower crouch shelter cringe huddle peep peek peer shrink tuck curl duck".split())


def hidden_behind(s: Sentence, k: int, prep: str, at: int) -> bool:
    """Whether the phrase from k after "behind"/"under" at `at` is a thing people hide by, which the world
    lacks and no word for a room heads (module doc)."""
    if prep not in _BEHIND:
        return False
    v = at - 1
    while v >= 0 and (s.low[v] in ("back", "straight", "right", "away", "down", "from", "out") or s.low[v].endswith("ly")):
        v -= 1
    if v < 0 or not (verb_lemma(s.low[v]) in _HIDING or s.verb(v) in _HIDING or _base(s.low[v]) in _HIDING or
                     hides_by_moving(s, v)):
        return False
    end = k
    while end < s.n and s.w[end].pos in ("DET", "ADJ", "NOUN", "PROPN"):
        end += 1
    if end == k or s.w[end - 1].pos not in ("NOUN", "PROPN"):
        return False
    head = lemma(s.low[end - 1])
    return head not in ROOM_HEADS and not s.index.knows(head) and not s.index.knows(s.low[end - 1])


def _base(word: str) -> str:
    """A verb's base form by rule ("crouches", "cowered", "hiding", "ducks")."""
    for ending in ("ches", "shes", "ing", "ed", "es", "s"):
        if word.endswith(ending) and len(word) > len(ending) + 2:
            cut = word[: len(word) - len(ending)]
            if ending in ("ches", "shes"):
                return cut + ending[:2]
            return cut if cut in _HIDING else cut + "e"
    return word
