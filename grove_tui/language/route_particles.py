"""What may stand between a person taken along and the route they are taken on (round 27): a
particle of the verb ("a carer helps Dorothy down to the lounge", "a porter wheels Mr Li up to
ward B", "a nurse walks Gran over to the pharmacy") and an aside about them, between commas ("a
carer helps Dorothy, on her walking frame, from the day room to the hairdresser's"). The route
still starts after them."""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from grove_tui.language.sentence import Sentence

_PARTICLES = frozenset("up down over round around along back across off".split())
# Route words a particle may come before ("down to", "back into", "over towards").
_AFTER_PARTICLE = frozenset("to into onto towards toward from through".split())
_ASIDE_WORDS = 7


def route_start(s: Sentence, k: int) -> int:
    """The word where the route starts at or after word k: past an aside between commas and a
    particle before a route word; k itself when neither is there. An aside that names them again
    ("Tom, a shoplifter, ...") is no aside of this kind."""
    if k < s.n and s.low[k] == "," and k > 0:
        close = next((j for j in range(k + 1, min(s.n, k + 2 + _ASIDE_WORDS)) if s.low[j] == ","), None)
        if close is not None and close + 1 < s.n and close > k + 1 and \
                s.w[k + 1].pos not in ("DET", "NOUN", "PROPN", "NUM", "PRON") and \
                all(s.w[j].pos not in ("VERB", "AUX") or s.w[j].tag in ("VBG", "VBN") for j in range(k + 1, close)):
            k = close + 1  # ", on her walking frame,"
    if k + 1 < s.n and s.low[k] in _PARTICLES and s.low[k + 1] in _AFTER_PARTICLE:
        k += 1  # "down to the lounge"
    return k
