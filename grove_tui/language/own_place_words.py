"""A bare word of a chat item placed in "his" or "her" own place, before the parse ("..., gaffer in his
office"): read as one person, so `bare_items` writes "a" before it (the parsed check is
language/own_place_items.py). Kept apart so the text pass needs no parsed sentence."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.tokens import lemma

HIS_OR_HER = frozenset({"his", "her"})
AT = frozenset({"in", "at", "by", "on", "inside", "behind"})


def own_place(noun: str, prep: str, possessive: str) -> bool:
    """Whether a bare word of a chat item, before the parse, is placed in his or her own place ("gaffer in
    his office"): a singular word, no word of the lists for a thing, an animal or the robot."""
    return prep in AT and possessive in HIS_OR_HER and noun.isalpha() and len(noun) >= 3 and \
        lemma(noun) == noun and noun not in lx.DETERMINERS and noun not in lx.STOPWORDS and \
        noun not in lx.NON_PEOPLE and noun not in lx.ROBOT_WORDS and noun not in lx.CARRYING_THINGS
