"""A place the world lacks, said as another kind of a fixture it has: "the petrol kiosk" of a world
whose only kiosk is the coffee kiosk, "the fuel kiosk", "the shoe shop" where there is a pet shop.

Every name of the world's place qualifies the head with its own word ("coffee kiosk", "coffee stand"),
and the phrase qualifies it with another: a kind of that head of its own. Such a modifier must be near
the place's own words by meaning, nearer than a modifier of a head the world leaves unqualified; and a
modifier the parser's vocabulary lacks ("petrol", British) still names a kind, unless it is spelt like
one of the place's own words ("chek" of "check-in"): a misspelling says no kind, and the phrase as a
whole decides, as before.
"""

from __future__ import annotations

from collections.abc import Sequence
from difflib import SequenceMatcher
from typing import TYPE_CHECKING

import numpy as np

from grove_tui.language.meaning import MiniLM, Vectors
from grove_tui.language.parser import known_word

if TYPE_CHECKING:
    from grove_tui.language.places import PlaceEntry


def _query_vector(model: MiniLM, text: str) -> Vectors:
    from grove_tui.language.places import _query_vector as cached  # the index's cache of phrase vectors

    return cached(model, text)

# The modifier of another kind of the same head against the place's own word before it: synonyms and
# things sold there come at 0.54-0.62 ("espresso" 0.56 and "latte" 0.54 from "coffee", "tea" 0.62),
# other kinds no nearer than 0.50 ("fuel" 0.50, "petrol" 0.43, "snack" 0.43 from "coffee", "shoe" 0.30
# from "pet").
MODIFIER_OF_KIND = 0.52
# A word spelt this like one of the place's own words is a misspelling of it ("chek" and "check").
_MISSPELT = 0.75


def names_a_kind(word: str, entry: PlaceEntry) -> bool:
    """Whether a modifier before a head is a word naming a kind ("fuel", "petrol"), not a misspelling of
    one of the place's own words ("chek" of "check")."""
    if known_word(word):
        return True
    return len(word) >= 4 and word.isalpha() and not _spelt_like(word, entry)


def _spelt_like(word: str, entry: PlaceEntry) -> bool:
    return any(word != t and SequenceMatcher(None, word, t).ratio() >= _MISSPELT for t in entry.tokens)


def kind_agrees(entry: PlaceEntry, modifiers: Sequence[str], head: str) -> bool:
    """Whether the modifiers of a phrase ("espresso" of "the espresso stand") are near in meaning to the
    place's own words before the same head ("coffee" of "coffee stand"), word against word: the place's
    other names ("barista", "coffee counter") do not count, for a word near them is no kind of its head."""
    model = MiniLM.shared()
    own = {" ".join(p[:p.index(head)]) for p in entry.phrases if head in p and p.index(head) > 0}
    if model is None or not own or not modifiers or any(_spelt_like(t, entry) for t in modifiers):
        return True  # "the chek-in hall": a misspelling of the place's own word, the phrase as a whole decides
    said = _unit(_query_vector(model, " ".join(modifiers)))
    return max(float(np.dot(said, _unit(_query_vector(model, word)))) for word in own) >= MODIFIER_OF_KIND


def _unit(vector: Vectors) -> Vectors:
    norm = float(np.linalg.norm(vector))
    return vector / norm if norm else vector
