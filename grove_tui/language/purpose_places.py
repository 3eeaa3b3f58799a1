"""Where a purpose said with "for" is done, right after it (round 69): "a trio of students go for coffee
in the café", "two porters nip out for a smoke by the back door", "queue for tickets at the kiosk". The
place after the purpose is where it is done: where people going for it go (or stay, when they stay), as
"to catch the train at platform 1" is (clauses.py). A walk gone for ("go for a stroll in the garden") is
done about the place, not at it, and stays as it was."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import lemma

# Prepositions of the place a purpose is done at.
_AT = frozenset({"at", "in", "inside", "by", "near"})


def place_after_purpose(s: Sentence, i: int, end: int) -> int | None:
    """The index of the preposition right after the purpose "for ..." from i to end (exclusive) when it
    opens the place the purpose is done at; None otherwise."""
    if end >= s.n or s.low[end] not in _AT or end + 1 >= s.n or s.low[end + 1] not in lx.DETERMINERS:
        return None
    said = [lemma(w) for w in s.low[i + 1:end] if w not in lx.DETERMINERS]
    if not said or lx.INTENT_VERBS.get(said[-1]) in ("walk", "wander") or said[-1] in ("walk", "stroll", "wander",
                                                                                       "jog", "run", "ride", "look"):
        return None  # "for a stroll in the garden": about the place
    return end
