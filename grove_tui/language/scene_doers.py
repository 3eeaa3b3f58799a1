"""People listed after an order to set a scene, each with what they are doing (round 44): "Have a couple
of cleaners wiping the tables and a lone first-aider sitting on the sofas", "Have both toddlers sprawled on
the couch and Grandpa doing the crossword at the kitchen table", "Show two porters pushing trolleys and a
nurse waiting by the lifts". The order's verb ("have", "show", "put", "add", "want") takes a list of people
and a participle for each; the parser joins the later items to a place or a thing before them, and a word
for people the lexicon lacks ("first-aider") or a name with no verb of its own ("Grandpa") is no group.
A noun right after "and", a comma or the order's verb (past its determiners, counts and adjectives),
right before a participle of a verb, in a sentence opened by such an order, is a person doing that."""

from __future__ import annotations

from typing import TYPE_CHECKING

from grove_tui.language import lexicon as lx
from grove_tui.language.object_verbs import english_verb

if TYPE_CHECKING:
    from grove_tui.language.sentence import Sentence

# Orders that set a scene with people in it, opening the sentence.
_ORDERS = frozenset({"have", "show", "put", "add", "want", "include", "give", "place", "stick", "get"})
# What may stand before such an item's noun: the list's joints and the order's own words.
_JOINTS = frozenset({"and", ",", "plus", "+", "also"})
_IN_PHRASE = frozenset({"DET", "NUM", "ADJ", "PROPN", "NOUN"})


def _opened_by_an_order(s: Sentence, i: int) -> int | None:
    """The index of the order that opens the sentence of word i, else None."""
    first = i
    while first > 0 and s.w[first - 1].sentence == s.w[i].sentence:
        first -= 1
    k = first + 1 if s.low[first] in ("please", "also", "then", "now") else first
    if k < s.n and s.low[k] == "let" and k + 1 < s.n and s.low[k + 1] in ("'s", "us"):
        k += 2  # "let's have ..."
    return k if k < i and s.low[k] in _ORDERS else None


def _participle(s: Sentence, k: int) -> bool:
    """Whether the word at k is a participle of a verb ("sitting", "sprawled", "cooking", tagged a noun)."""
    w = s.w[k]
    if w.tag in ("VBG", "VBN"):
        return english_verb(w.lemma) or w.lemma in lx.INTENT_VERBS
    low = w.lower
    if w.tag != "NN" or not low.endswith("ing") or len(low) < 6:
        return False
    stem = low[:-3]
    return any(english_verb(b) for b in (stem, stem + "e", stem[:-1] if stem[-1:] == stem[-2:-1] else stem))


def scene_doer(s: Sentence, i: int) -> bool:
    """Whether the noun at i is one of the people an opening order lists, with their participle after it
    (module doc)."""
    w = s.w[i]
    if w.pos not in ("NOUN", "PROPN") or i + 1 >= s.n or not _participle(s, i + 1):
        return False
    if s.low[i] in lx.ROBOT_WORDS or s.lemma(i) in lx.NON_PEOPLE or not s.low[i].isalpha():
        return False
    if s.index.knows(s.lemma(i)) and s.lemma(i) not in lx.PERSON_NOUNS:
        return False  # "the tables being wiped": a place or thing of the world
    order = _opened_by_an_order(s, i)
    if order is None:
        return False
    k = i
    while k > order + 1 and (s.w[k - 1].pos in _IN_PHRASE or s.low[k - 1] == "-") and s.low[k - 1] not in _JOINTS:
        k -= 1  # "a lone first-aider", "both toddlers"
    return k == order + 1 or s.low[k - 1] in _JOINTS
