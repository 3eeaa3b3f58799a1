"""Names made of a verb the reader otherwise drops and its particle ("make-up", "make up room",
"makeover"): the two words are one word of the name, "makeup", on both sides of a match (the world's
aliases and the prompt's phrase), so "the make-up room" is not just "the room" (which the green room
said before would answer) and "wait in make-up" names a place.

Only verbs that are stopwords join: a name like "check-in desk" keeps its verb ("check"), which
already tells it apart."""

from __future__ import annotations

from collections.abc import Callable, Sequence

# Stopword verbs that start a compound noun with a particle: "make-up", "make-over", "let-out".
_VERBS = frozenset({"make", "makes", "let"})
_PARTICLES = frozenset({"up", "over", "out", "off", "in", "down"})


def joined(ws: Sequence[str], k: int) -> tuple[str, int] | None:
    """The one word that word k and the particle after it make ("make", "up" -> "makeup"; a hyphen
    may stand between), and the index after the particle; None when no such compound starts at k."""
    if ws[k] not in _VERBS:
        return None
    p = k + 2 if k + 2 < len(ws) and ws[k + 1] == "-" else k + 1
    if p < len(ws) and ws[p] in _PARTICLES:
        return ws[k].removesuffix("s") + ws[p], p + 1
    return None


def first_lemma(ws: Sequence[str], lemma: Callable[[str], str]) -> str:
    """The first word of a name said from ws[0] as names are indexed: "make-up room": "makeup"."""
    one = joined(ws, 0) if ws else None
    return one[0] if one is not None else lemma(ws[0]) if ws else ""


def known_compound(ws: Sequence[str], k: int, knows: Callable[[str], bool]) -> bool:
    """Whether a compound starting at k is a word of the world's names ("in make-up": a place, not a
    preposition before a verb)."""
    one = joined(ws, k)
    return one is not None and knows(one[0])
