"""Hazards said as a security scare, a tripped detector or dangerous weather (round 22): "an unattended
holdall is spotted under the rack", "a suspicious package is found", "the common room's smoke detector
trips", "lightning is spotted nearby". A bag left alone that someone finds, a detector that goes off or
a storm's danger is a hazard cue, so people who have to get out after it evacuate (`hazards.py`)."""

from __future__ import annotations

from grove_tui.language.sentence import Sentence

# Things whose finding, left alone, is a scare.
_BAGS = frozenset("bag bags holdall holdalls suitcase suitcases package packages parcel parcels rucksack "
                  "rucksacks backpack backpacks case box device".split())
# Words that say a thing is left alone ("an unattended holdall", "a suspicious package").
_ALONE = frozenset("unattended abandoned suspicious unclaimed suspect ownerless".split())
# Verbs of finding it ("is spotted", "has been found", "is reported").
_FOUND = frozenset("spotted found discovered reported noticed seen".split())
# Weather that closes a place ("lightning is spotted nearby, so the ride shuts").
_WEATHER = frozenset("lightning thunder thunderstorm thunderstorms tornado hurricane".split())
_DETECTORS = frozenset({"detector", "detectors"})
_TRIPPING = frozenset("trip trips tripped tripping go goes went sound sounds sounded beep beeps beeped "
                      "activate activates activated".split())


def scare_cue(s: Sentence, i: int) -> bool:
    """Whether the word at i is a bag left alone, or found ("is spotted"), a detector that trips or
    dangerous weather."""
    low = s.low
    if low[i] in _WEATHER and s.w[i].pos in ("NOUN", "PROPN"):
        return True
    if low[i] in _DETECTORS:
        return i + 1 < s.n and low[i + 1] in _TRIPPING
    if low[i] not in _BAGS or s.w[i].pos not in ("NOUN", "PROPN"):
        return False
    if i >= 1 and low[i - 1] in _ALONE:
        return True
    k = i + 1
    while k < s.n and k <= i + 3 and low[k] in ("is", "was", "has", "have", "been", "just", "being"):
        k += 1
    return k > i + 1 and k < s.n and low[k] in _FOUND
