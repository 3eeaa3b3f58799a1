"""Verbs of a body of people coming down on a place (round 26): "a coachload of members descends on
the café", "twenty pupils converge on the gift shop", "the fans swoop on the bar", "shoppers close in
on the tills". The place after "on"/"upon" is where they go, not where they stand: they walk there (the robot
"closed in on" is no place, and is left to the robot's reader).
The reader knows "head to" well, so the phrase is said that way before the sentence is read, in the
verb's own form ("descends on" -> "heads to", "converging upon" -> "heading to")."""

from __future__ import annotations

import re

# The verb's stem with its endings, then any particle; "on"/"upon" after.
_CONVERGING = re.compile(
    r"\b(?:descend|converge|swoop|zero(?:e)?|home|clos)(?P<end>s|es|ed|d|ing|e)?"
    r"(?:\s+(?:in|down))?\s+(?:on|upon)\s+(?=(?:the|a|an|their|our|his|her|its|this|that)\b)"
    r"(?!\w+\s+(?:\w+\s+)?(?:robot|bot|droid|machine)\b)",
    re.IGNORECASE)
_ENDS = {"s": "s", "es": "s", "ed": "ed", "d": "ed", "ing": "ing"}


def as_heading(text: str) -> str:
    """The text with a verb of coming down on a place said as heading to it."""
    def say(m: re.Match[str]) -> str:
        word = m.group(0).split()[0].lower()
        if word.startswith(("home", "clos", "zero")) and not re.search(r"\s(?:in)\s", m.group(0)):
            return m.group(0)  # "close on the door", "home on Tuesday": only "close in on", "home in on"
        end = _ENDS.get(m.group("end") or "", "")
        if word.startswith("clos") and word in ("close", "closes", "closed", "closing"):
            end = {"close": "", "closes": "s", "closed": "ed", "closing": "ing"}[word]
        if word.startswith("zero") and word.endswith("es"):
            end = "s"
        return f"head{end} to "
    return _CONVERGING.sub(say, text)
