"""Hazards said as weather that damages a place (round 51): "a gust of wind lifts the side of the tent",
"gales buckle the air dome", "the storm rips the canopy off", "a squall blows the awning down", "with the
roof torn off by the storm". Strong wind or a storm that damages the place people are in is a hazard cue,
so people who hurry out after it evacuate (`hazards.py`). Weather that only turns ("with the wind picking
up", "a gale blows outside") damages nothing: people who leave then walk, as the sets label them.
"""

from __future__ import annotations

from grove_tui.language.sentence import Sentence

# Strong wind and storms (rain and snow alone are no danger to a building in the sets' labels).
_WINDS = frozenset("wind winds gust gusts gale gales storm storms squall squalls whirlwind tempest".split())
# Verbs of damage, every form ("lifts", "ripped", "is tearing", "torn").
_DAMAGING = frozenset(f"{v}{end}" for v in ("lift", "rip", "buckl", "flatten", "toppl", "snap", "smash", "wreck",
                                            "damag", "collaps", "uproot", "shred", "split", "peel")
                      for end in ("", "s", "ed", "d", "ped", "ping", "ing", "es", "e")) | frozenset(
    "tear tears tore torn tearing bring brings brought bringing".split())
# "blows" damages only with its particle ("blows the roof off", "blew the awning down").
_BLOWS = frozenset("blow blows blew blowing blown".split())
_PARTICLES = frozenset("off down over in away apart".split())
# Words that may stand between the weather word and its verb ("a gust of wind suddenly lifts").
_BETWEEN = frozenset("of wind winds suddenly then just has have had is are was were sudden strong violent "
                     "powerful fierce freak".split())


def damage_cue(s: Sentence, i: int) -> bool:
    """Whether the word at i is strong weather whose verb damages something (see the module doc)."""
    low = s.low
    if low[i] not in _WINDS or s.w[i].pos not in ("NOUN", "PROPN"):
        return False
    if i >= 3 and low[i - 2] == "by" and any(low[k] in _DAMAGING or low[k] in _BLOWS for k in range(max(0, i - 5), i - 2)):
        return True  # "with the roof torn off by the storm"
    k = i + 1
    while k < s.n and k <= i + 4 and low[k] in _BETWEEN:
        k += 1
    if k >= s.n:
        return False
    if low[k] in _DAMAGING:
        return low[k] != "lift" or s.w[k].pos == "VERB"
    return low[k] in _BLOWS and any(low[j] in _PARTICLES for j in range(k + 1, min(k + 6, s.n)))
