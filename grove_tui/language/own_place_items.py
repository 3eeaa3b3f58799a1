"""One person said by a word no list knows, placed in "his" or "her" own place as an item of a chat list
with no verb ("a guy at the printer, gaffer in his office", "2 nurses by the lifts, the sister at her
desk"): a singular noun opening an item (after a comma, "and", "+" or at the start, maybe with "a",
"an" or "the"), followed at once by a place preposition and "his" or "her", is one person: no place,
thing or animal of the lists is in "his" or "her" own place."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.place_modifiers import names_a_place
from grove_tui.language.sentence import Sentence
from grove_tui.language.own_place_words import AT, HIS_OR_HER

_OPENERS = frozenset({"a", "an", "the", "our", "their", "some"})
_ITEM_STARTS = frozenset({",", ";", "and", "+", "&", "plus"})


def own_place_item(s: Sentence, i: int) -> bool:
    """Whether word i is the one person of a verbless chat item placed in his or her own place."""
    if i + 2 >= s.n or s.low[i + 1] not in AT or s.low[i + 2] not in HIS_OR_HER:
        return False
    if s.w[i].pos not in ("NOUN", "PROPN") or not s.low[i].isalpha() or len(s.low[i]) < 3:
        return False
    lem = s.lemma(i)
    if lem != s.low[i] or names_a_place(s.index, lem) or s.index.knows(lem) or lem in lx.NON_PEOPLE or \
            lem in lx.ROBOT_WORDS or lem in lx.STOPWORDS or lem in lx.NON_PLACES or lem in lx.BUILDING_WORDS or \
            lem in lx.HAZARD_NOUNS or lem in lx.DURATION_UNITS or lem in lx.CARRYING_THINGS:
        return False
    k = i - 1 if i > 0 and s.low[i - 1] in _OPENERS else i
    return k == 0 or s.low[k - 1] in _ITEM_STARTS

