"""Being crammed into a place (round 54): "nine porters are crammed into the staff lounge", "forty fans
are packed into the bar", "six of us were squeezed into the lift". After a form of "be" the participle
says how full the place is, not a going there: the people are in it, as "are crammed in the staff
lounge" says, so "into" is written "in" before the sentence is parsed (a subset said after it, "four of
them head down to the canteen", then goes from there). "They cram into the lift", "get squeezed into
it" stay a going in."""

from __future__ import annotations

import re

_BE = r"(?:am|is|are|was|were|'re|'s|been|being)"
_ADVERB = r"(?:(?:all|still|already|now|tightly|tight|firmly|happily|uncomfortably|currently)\s+)?"
_FULL = r"(?:crammed|packed|squeezed|squashed|wedged|jammed|crushed|stuffed|squished|shoehorned|penned|herded)"
_CRAMMED = re.compile(r"\b(" + _BE + r"\s+" + _ADVERB + _FULL + r"\s+)into\b", re.IGNORECASE)


def with_crammed_in(text: str) -> str:
    """The text with "<be> crammed into X" written "<be> crammed in X" (see the module doc)."""
    return _CRAMMED.sub(lambda m: m.group(1) + "in", text)
