"""How a person taken along is held, said after their name (round 28): "a daughter takes Edith
Baxter arm in arm out of the lounge", "a guard walks Tom by the hand to the exit". The parser took
the manner phrase for the verb's object or a place, and the person taken along was lost; it says
only how they go together, so it is left out before the sentence is read ("takes Edith Baxter out
of the lounge"), and the named person is the second group that follows the taker. Only a phrase
right after a capitalised name and before a word of a route is read so ("Two friends walk arm in
arm to the café" keeps its words)."""

from __future__ import annotations

import re

_HELD = re.compile(r"(\b[A-Z][a-z]+)(\s*,?\s+(?:arm in arm|arm-in-arm|hand in hand|hand-in-hand|"
                   r"by the (?:hand|arm|elbow)|by (?:his|her|their) (?:hand|arm|elbow))\s*,?)"
                   r"(?=\s+(?:from|out|into|to|in|across|through|down|up|back|over|along|round|around|towards?|"
                   r"inside|outside|off|away|past|onto)\b)")


def without_held_hands(text: str) -> str:
    """The text with "arm in arm"/"by the hand" after a person's name taken along left out."""
    return _HELD.sub(lambda m: m.group(1), text)
