"""The first item of an imperative that places people (round 33): "Put three on the bikes and two by the
wall bars", "Have two in the lobby and three in the café". A count right after the scene's verb, with
a place after it, counts people as the items after "and" do."""

from __future__ import annotations

from typing import TYPE_CHECKING

from grove_tui.language import lexicon as lx

if TYPE_CHECKING:
    from grove_tui.language.sentence import Sentence

# Verbs of an imperative that places people in the scene.
_PLACING = lx.SCENE_VERBS & frozenset("put have add place position station stick want need include".split()) | \
    frozenset({"station", "stick", "pop", "seat", "sit", "stand"})


def scene_imperative(s: Sentence, v: int) -> bool:
    """Whether word v is a verb of placing people that opens its sentence ("Put", "please have")."""
    if s.low[v] not in _PLACING:
        return False
    return v == 0 or s.is_punct(v - 1) or s.w[v - 1].sentence != s.w[v].sentence or s.low[v - 1] in ("please", "then",
                                                                                                        "and", "also")
