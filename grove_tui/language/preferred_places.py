"""A place chosen over another, round 71: "choose the library over the state dining room", "pick the café
over the lounge", "prefer the garden to the bar", "opt for the quiet room". The place chosen is where
they go; the one it is chosen over (after "over", or "to" of "prefer") is a place they do not go to,
never their destination. Read for language/clauses.py."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.sentence import Sentence

# Verbs of choosing between places; their object is where people go.
PREFERRING_VERBS = frozenset("choose pick prefer favour favor select opt".split())
# Words after the chosen place that say what it is chosen over ("prefer ... to" only after prefer).
_OVER = frozenset({"over", "above"})


def chosen_at(s: Sentence, i: int) -> int | None:
    """Where the place a verb of choosing at i names begins ("choose the library", "opt for the
    snug"), or None when i is no such verb or a thing follows it ("pick up a parcel")."""
    if s.verb(i) not in PREFERRING_VERBS or s.after_determiner(i):
        return None
    k = i + 1
    if k < s.n and s.low[k] in ("for", "instead") and s.verb(i) in ("opt", "choose", "select"):
        k += 1  # "opt for the library"
    return k if k < s.n and (s.low[k] in lx.DETERMINERS or s.index.knows(s.lemma(k))) else None


def over_at(s: Sentence, verb: int, end: int) -> int | None:
    """Where the place the chosen one is chosen over begins, right after the chosen place's end
    ("over the state dining room", "to the bar" after "prefer"), or None."""
    if end >= s.n:
        return None
    word = s.low[end]
    if word in _OVER or (word == "to" and s.verb(verb) == "prefer"):
        return end + 1 if end + 1 < s.n else None
    return None
