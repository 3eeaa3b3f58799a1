"""Someone kept at a place by their attention (round 69): "a team leader is glued to the wallboard", "two
fans stay rooted to the barrier", "a clerk is chained to the front desk". Read as a way to the place ("to
the wallboard": a walk there); said as being at it ("is at the wallboard"), they stay there. Only when the
world names what they are glued to: "glued to her phone", "rooted to the spot" and the robot
(robot_sticking.py: sticking to it is following it) are left as said."""

from __future__ import annotations

import re

from grove_tui.language import lexicon as lx
from grove_tui.language.places import PlaceIndex
from grove_tui.language.tokens import phrase_lemmas, words

_GLUED = re.compile(r"\b(?:glued|rooted|riveted|chained|welded|fixed)\s+to\s+(?P<np>(?:the|a|an|his|her|their|its)\s+"
                    r"[\w'’ -]+?)(?=\s*(?:[,;:.!?]|\b(?:and|while|whilst|but|as|in|on|at|by|with|near|beside|wait|waits|sit|sits)\b|$))",
                    re.IGNORECASE)  # "glued to the cricket in the living room": what holds them ends at "in"


def as_kept_at(text: str, index: PlaceIndex) -> str:
    """The text with "glued to <a place the world names>" said as "at <that place>" (module doc)."""
    def said(m: re.Match[str]) -> str:
        said_words = words(m.group("np"))
        if any(w in lx.ROBOT_WORDS for w in said_words):
            return m.group(0)
        found = index.match(tuple(phrase_lemmas(said_words)))
        return f"at {m.group('np')}" if found is not None and found.exact else m.group(0)
    return _GLUED.sub(said, text)
