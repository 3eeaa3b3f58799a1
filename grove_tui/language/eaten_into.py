"""Food said by a verb of eating into it (round 51): "a crew tucking into curry in the mess", "kids dig
into their packed lunches", "bites into a pasty", "gets stuck into a fry-up". Whatever follows "into"
after such a verb is eaten, no place, so a world lacking it has nothing to refuse. "tucked into a corner"
(a room word) and a place the world names ("tucks into the canteen") stay places."""

from __future__ import annotations

from grove_tui.language.hazards import ROOM_HEADS
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import lemma, verb_lemma

# Verbs that, with "into", say eating ("tuck into", "dig into", "bite into", "get stuck into").
_EATING_INTO = frozenset("tuck dig bite wolf chomp munch".split())
_ENDS = frozenset("PUNCT ADP CCONJ SCONJ AUX PRON VERB".split())


def eaten_into(s: Sentence, k: int, prep: str, at: int) -> bool:
    """Whether the phrase from k after "into" at `at` is food eaten (see the module doc)."""
    if prep != "into" or at < 1:
        return False
    v = at - 1
    said = s.low[v] == "teeth" or (s.low[v] == "stuck" and v >= 1 and verb_lemma(s.low[v - 1]) in ("get", "be"))
    if not said and not ({verb_lemma(s.low[v]), s.lemma(v), s.verb(v)} & _EATING_INTO):
        return False  # "sinks her teeth into", "gets stuck into", "tucking into"
    end = k
    while end < s.n and s.w[end].pos not in _ENDS and s.low[end] not in ("and", "or"):
        end += 1
    if end == k:
        return False
    nouns = [s.low[x] for x in range(k, end) if s.w[x].pos in ("NOUN", "PROPN", "ADJ")]
    return not any(w in ROOM_HEADS or lemma(w) in ROOM_HEADS or s.index.knows(lemma(w)) for w in nouns)
