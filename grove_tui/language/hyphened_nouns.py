"""A verb and its particle joined by a hyphen name a thing or a place, not an act (round 50): "walks to
check-in", "drag their cases to check-in", "head to drop-off", "queue at the sign-in". After "to" such a
word is where they go, not a purpose "to check" (sentence.py `verb_follows`); written apart ("to check
in at the desk") it stays a purpose."""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from grove_tui.language.sentence import Sentence

_PARTICLES = frozenset("in out off up on down over through by away".split())


def hyphened_particle_noun(s: Sentence, k: int) -> bool:
    """Whether the word at k is joined by a hyphen to a particle after it ("check-in", "drop-off")."""
    return k + 2 < s.n and s.hyphen_inside(k + 1) and s.low[k + 2] in _PARTICLES
