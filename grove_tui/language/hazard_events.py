"""Hazards said as an event (round 18): "water pours through the ceiling", "a pipe bursts", "the
sprinklers go off", "a ceiling panel falls". A thing of the building that fails, then a verb of its
failing within a word or two: a hazard cue, so people who leave after it evacuate (`hazards.py`)."""

from __future__ import annotations

from grove_tui.language.sentence import Sentence

# Things of a building whose failing is a hazard.
_FAILING_THINGS = frozenset("pipe pipes main mains boiler tank ceiling ceilings roof panel panels tile tiles "
                            "plaster water sprinkler sprinklers shelving scaffolding beam".split())
# Verbs of failing, every form ("bursts", "fell", "is pouring", "caves in").
_FAILING = frozenset(f"{v}{end}" for v in ("burst", "collapse", "pour", "gush", "flood", "leak", "cave", "crash")
                     for end in ("", "s", "ed", "d", "ing")) | frozenset(
    "fall falls fell falling fallen explode explodes exploded exploding split splits splitting".split())
# Verbs of a sprinkler system starting ("the sprinklers go off", "come on", "are set off", "trip").
_STARTING = frozenset("go goes went going gone come comes came coming set trigger triggers triggered "
                      "activate activates activated start starts started kick kicks kicked "
                      "trip trips tripped tripping".split())
_SPRINKLERS = frozenset({"sprinkler", "sprinklers"})
# Words that may stand between the thing and its verb ("the pipe suddenly bursts", "is pouring").
_BETWEEN = frozenset("suddenly just then has have had is are was were starts start begins begin system "
                     "systems panel panels tiles tile".split())


def event_cue(s: Sentence, i: int) -> bool:
    """Whether the word at i names a thing of the building that then fails (see the module doc)."""
    if s.low[i] not in _FAILING_THINGS or s.w[i].pos not in ("NOUN", "PROPN", "VERB"):
        return False
    k = i + 1
    while k < s.n and k <= i + 3 and s.low[k] in _BETWEEN:
        k += 1
    if k >= s.n:
        return False
    if s.low[k] in _FAILING and not (s.low[i] == "water" and s.low[k].startswith("fall")):
        return True
    return s.low[i] in _SPRINKLERS and s.low[k] in _STARTING
