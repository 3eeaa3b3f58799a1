"""How long a group that looks at the robot looks: a glance or a stare.

"Two cleaners glance at the robot as it passes" and "the children look at the robot" ask for a look at
least once, for a short while; "the children stare at the robot", "visitors watch the robot" and "keep
looking at it" ask for a look for most of the time it is near. The reading's robot_interaction is "look"
for all of them; this is the difference, read from the group's own words (GroupReading.text):

    look_span(group)  # "glance" | "watch" | None (the group does not look at the robot)

A look whose verb is not found reads as a glance: the lesser claim, never a stare the sentence did not ask.
"""

from __future__ import annotations

from typing import Literal

from grove_tui.language.model import GroupReading
from grove_tui.language.tokens import words

LookSpan = Literal["glance", "watch"]
GLANCE: LookSpan = "glance"
WATCH: LookSpan = "watch"

# Verbs of a sustained look: their eyes stay on it while it is near.
_WATCH_VERBS = ("watch", "stare", "gaze", "observe", "study", "gape", "gawp", "gawk", "eye", "film", "ogle",
                "scrutinise", "scrutinize", "monitor", "track", "survey", "contemplate")
# Verbs of a look at least once, for a short while.
_GLANCE_VERBS = ("glance", "look", "glimpse", "peek", "peep", "notice", "spot", "see", "peer", "wave", "regard",
                 "photograph", "snap", "check", "turn", "crane", "smile", "point")
# Words that make any look last: "keep looking at it", "look at the robot the whole time".
_KEEP = frozenset({"keep", "keeps", "kept", "keeping"})
_ALL_ALONG = (("the", "whole", "time"), ("all", "the", "time"), ("constantly",), ("continuously",),
              ("intently",), ("closely",), ("fixedly",), ("all", "along"), ("throughout",), ("never", "take"),
              ("can't", "take"), ("cannot", "take"), ("eyes", "on"), ("eye", "on"), ("with", "their", "eyes"),
              ("with", "his", "eyes"), ("with", "her", "eyes"), ("every", "move"), ("as", "long", "as"))
_ROBOT_WORDS = frozenset({"robot", "robots", "it", "machine", "droid"})


def _forms(base: str) -> set[str]:
    stem = base[:-1] if base.endswith("e") else base
    out = {base, base + "s", base + "es", base + "ed", base + "d", stem + "ing", stem + "ed"}
    if len(base) >= 3 and base[-1] not in "aeiouwy" and base[-2] in "aeiou" and base[-3] not in "aeiou":
        out |= {base + base[-1] + "ing", base + base[-1] + "ed"}  # "spotting", "snapped"
    if base == "see":
        out |= {"saw", "seen", "seeing", "sees"}
    if base == "eye":
        out |= {"eyeing", "eying"}
    return out


_WATCH_FORMS = {f for v in _WATCH_VERBS for f in _forms(v)}
_GLANCE_FORMS = {f for v in _GLANCE_VERBS for f in _forms(v)} | {"glances", "photo", "photos", "picture",
                                                                  "pictures", "selfie", "selfies", "glimpse"}


def _has(tokens: list[str], phrase: tuple[str, ...]) -> bool:
    n = len(phrase)
    return any(tuple(tokens[i:i + n]) == phrase for i in range(len(tokens) - n + 1))


def look_span_of_text(text: str) -> LookSpan:
    """The span of a look the words ask (module doc); a glance when no verb of looking is found."""
    tokens = words(text.replace("’", "'"))
    if any(_has(tokens, p) for p in _ALL_ALONG):
        return WATCH
    first_robot = next((i for i, t in enumerate(tokens) if t in _ROBOT_WORDS), len(tokens))
    before = tokens[:first_robot] or tokens
    # the verb of looking nearest before the robot governs it ("watch TV and glance at the robot": glance)
    for i in range(len(before) - 1, -1, -1):
        t = before[i]
        if t in _WATCH_FORMS:
            return WATCH
        if t in _GLANCE_FORMS:
            kept = i > 0 and before[i - 1] in _KEEP or i > 1 and before[i - 2] in _KEEP
            return WATCH if kept and t.endswith("ing") else GLANCE
    return GLANCE


def look_span(group: GroupReading) -> LookSpan | None:
    """A looking group's span: "glance" (at least once, a short while) or "watch" (most of the time the robot
    is near); None when the group does not look at the robot."""
    if group.robot_interaction != "look":
        return None
    return look_span_of_text(group.text)
