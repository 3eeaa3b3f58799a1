"""Verbless chat items opened by a possessive (round 62): "our son on his xbox in bedroom 2, the missus @
kitchen table, gran napping in the armchair", "my wife in the kitchen, the lodger in the lounge". An
item with "the" ("the son in bedroom 2") was read as a person, but one with "our", "my" or "their" before
the person word and a place word right after it was lost (no verb claims it): such an item's
possessive is written "the" before the prompt is parsed. An item whose person has a verb ("our son is
in bedroom 2", "my wife sits in the kitchen") is left as it is."""

from __future__ import annotations

import re

from grove_tui.language import lexicon as lx
from grove_tui.language.tokens import lemma

_PLACED = r"(?:in|at|on|by|near|inside|outside|behind|beside|@)"
# An item's start (the text's start, a comma or a semicolon), a possessive, a person word, a place word.
_ITEM = re.compile(r"(?:^|(?<=[,;]\s))(?P<own>[Oo]ur|[Mm]y|[Tt]heir|[Yy]our)\s+(?P<who>[a-z]+)(?=\s+" + _PLACED + r"\s)")


def possessed_items(text: str) -> str:
    """The text with "the" for the possessive opening a verbless item of a person (see the module doc)."""
    return _ITEM.sub(_the, text)


def _the(m: re.Match[str]) -> str:
    who = m.group("who")
    if who not in lx.PERSON_NOUNS and lemma(who) not in lx.PERSON_NOUNS:
        return m.group(0)
    return ("The " if m.group("own")[0].isupper() else "the ") + who
