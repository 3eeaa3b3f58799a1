"""Little ones carried by the people said (round 28): "fifteen or so mums with babies in slings wait
in line", "a woman with a baby in a sling waits", "a dad with a toddler on his shoulders walks". The
reader found the babies a second group walking beside their parents; carried in a sling, in arms,
in a pram or on shoulders, they go where they are taken and take no room of their own, so the phrase
only describes the carriers and is left out before the sentence is read ("fifteen or so mums wait
in line"), one group. A child only "with" someone ("a mum with two toddlers") is untouched."""

from __future__ import annotations

import re

_CARRIED = re.compile(
    r",?\s+with\s+(?:(?:a|an|their|her|his|one|two|three|twin|small|tiny|young|little|newborn|sleeping)\s+){0,3}"
    r"(?:babies|baby|infants?|newborns?|toddlers?|tots?|little ones|kids?|children|child|nippers?)\s+"
    r"(?:in|on|strapped to|strapped into|asleep in|asleep on)\s+(?:(?:a|an|the|their|her|his|baby)\s+){0,2}"
    r"(?:slings?|arms|prams?|pushchairs?|buggy|buggies|strollers?|shoulders|hips?|backs?|carriers?|papooses?|laps?)"
    r"\b,?", re.IGNORECASE)


def without_carried_babies(text: str) -> str:
    """The text with "with babies in slings" and the like after the carriers left out (module doc)."""
    return _CARRIED.sub("", text)
