"""A zone said to shut (round 39): "Splash Falls shuts and the riders queuing for it hurry out", "the food
court closes, so sixty shoppers head for the main entrance", "the bar shuts down and ...". Everybody in a
zone that shuts leaves it, as from an emptied zone (`emptied.py`), so it is their start. Only the active
verb with no object is read so: "shuts the door" has one, and "the café is closed" says how it is, not
that anybody leaves. Whether the subject is a zone is the caller's to check."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import lemma

_CLOSING = frozenset("shuts closes shut closed".split())


def closing_end(s: Sentence, i: int) -> int | None:
    """The end of the subject that the word at i says shuts, or None (module doc)."""
    if i < 1 or s.low[i] not in _CLOSING or s.w[i].tag not in ("VBZ", "VBD", "VBP", "NNS"):
        return None
    if s.low[i - 1] in ("is", "are", "was", "were", "be", "been", "being", "has", "have", "had", "not"):
        return None
    nxt = s.low[i + 1] if i + 1 < s.n else ""
    if nxt in lx.DETERMINERS or (nxt and s.index.knows(lemma(nxt))):
        return None  # an object follows: "shuts the door", "closes the shutters"
    return i
