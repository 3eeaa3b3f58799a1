"""One place moved off for another, round 34: "heads off the second platform for the signal box",
"walks out of the cafeteria for the boiler house", "hurries from the bar for the exit". As after a
place a verb leaves ("leaves the ward for the canteen", language/place_contrast.py), "for" and a
determiner right after a place said with "off", "out of" or "from" a verb of going moves them from is
where they go: a place the world lacks there is refused, not read as what they go for."""

from __future__ import annotations

from typing import TYPE_CHECKING

from grove_tui.language import lexicon as lx
from grove_tui.language.tokens import verb_lemma

if TYPE_CHECKING:
    from grove_tui.language.place_phrases import Place
    from grove_tui.language.sentence import Sentence

_GOING = frozenset({"walk", "wander"})  # the intents of verbs that move people ("head", "hurry", "drift")
_FROM = frozenset({"from", "off"})


def moved_off_for(s: Sentence, before: Place, at: int) -> bool:
    """Whether the "for" at `at` comes right after `before`, a place a verb of going moves people off,
    out of or from, and is followed by a determiner ("for the signal box", not "for a smoke")."""
    if before.end != at or before.prep not in _FROM or at + 1 >= s.n or s.low[at + 1] not in ("the", "this", "that"):
        return False
    j = before.index - 1
    while j >= 0 and (s.w[j].pos == "ADV" or s.low[j] in ("off", "back")) and s.low[j] not in ("out",):
        j -= 1
    if j < 0:
        return False
    v = verb_lemma(s.low[j])
    return v in lx.DEPARTURE_VERBS or lx.INTENT_VERBS.get(v) in _GOING
