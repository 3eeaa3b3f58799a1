"""A noun that closes an unknown place phrase is its head, not a verb after the place (issue 29).

"towards the mountain bike trail.": "trail" is also a verb of following, and "mountain bike" happens to
match some bike entity loosely, so the place used to stop at "mountain bike" and the refusal named a
part of the phrase. A word the parser tags as a singular or plural noun, ending the phrase (the
sentence, a clause's comma or "and" follows), and after words that name no place exactly, is the head
of the phrase: the whole phrase is what is read (or refused). "the check-in hall queue at the desk"
(an exact name, then a word followed by more) keeps its reading."""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import lemma


def noun_head_ends(s: Sentence, phrase: Sequence[str], j: int) -> bool:
    """Word j, after the place words `phrase`, is a noun that ends the phrase and names no place alone."""
    if not s.w[j].tag.startswith("NN") or s.w[j].tag.startswith("NNP"):
        return False
    if j + 1 < s.n and not (s.is_punct(j + 1) or s.low[j + 1] in ("and", "or", "but")):
        return False
    match = s.index.match([lemma(x) for x in phrase])
    return match is not None and not match.exact


def place_before_verb(s: Sentence, phrase: Sequence[str], j: int) -> bool:
    """The words `phrase` are a place (or nothing in particular) and word j, a verb word, follows it:
    "in the cafeteria evacuate"; not the head noun of an unknown phrase ("the mountain bike trail.")."""
    lemmas = [lemma(x) for x in phrase]
    return s.index.is_nameless(lemmas) or (s.index.match(lemmas) is not None and not noun_head_ends(s, phrase, j))


def hyphened_name_word(s: Sentence, j: int) -> bool:
    """Whether the preposition at j is hyphened to a word the world's names have ("the under-twos room",
    "the over-sixties lounge"): a word of the place's name, not a new place phrase (round 69)."""
    return j + 2 < s.n and s.low[j + 1] == "-" and s.hyphen_inside(j + 1) and s.index.knows(lemma(s.low[j + 2]))
