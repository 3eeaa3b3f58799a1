"""Hazards said without a word of fire (round 72): trouble that breaks out ("a brawl breaks out", "a
brawl breaks out and the platform is closed", "a scuffle erupts; the floor is cleared": trouble that
closes a place, never trouble others run to break up) and a cooking pot that catches on the stove ("a pot
of rice catches on the hob", "the chip pan caught"). Each is a hazard cue, so people who leave or are
moved on after it evacuate (`hazards.py`)."""

from __future__ import annotations

from grove_tui.language.sentence import Sentence

# Trouble among people that clears a place when it breaks out.
_TROUBLE = frozenset("brawl brawls fight fights scuffle scuffles riot riots fracas melee mêlée punch-up "
                     "stampede stabbing shooting disturbance".split())
# Verbs of its breaking out ("breaks out", "erupts", "kicks off", "flares up").
_BREAKING = frozenset("break breaks broke breaking broken erupt erupts erupted erupting flare flares flared "
                      "flaring kick kicks kicked kicking start starts started starting".split())
_OUT = frozenset({"out", "off", "up"})
# Words that say the trouble closes or clears a place.
_CLOSING = frozenset("closed cleared shut evacuated cordoned sealed emptied".split())
# Cooking things that catch (burn) on a stove.
_VESSELS = frozenset("pot pots pan pans saucepan saucepans frying wok woks fryer fryers skillet casserole "
                     "chip".split())
_CATCHING = frozenset("catch catches caught catching".split())


def trouble_cue(s: Sentence, i: int) -> bool:
    """Whether the word at i is trouble that breaks out or a pot that catches (see the module doc)."""
    low = s.low
    if low[i] in _TROUBLE and s.w[i].pos in ("NOUN", "PROPN") and any(w in _CLOSING for w in low):
        k = i + 1
        while k < s.n and k <= i + 3 and low[k] in ("has", "have", "had", "suddenly", "just", "then", "is", "was"):
            k += 1
        if k < s.n and low[k] in _BREAKING:
            verb = low[k]
            return verb.startswith("erupt") or (k + 1 < s.n and low[k + 1] in _OUT)
        return False
    if low[i] in _CATCHING and (i + 1 >= s.n or low[i + 1] not in ("fire", "light", "the", "a", "an", "sight")):
        return any(low[x] in _VESSELS for x in range(max(0, i - 4), i)) and (
            i + 1 >= s.n or s.is_punct(i + 1) or low[i + 1] in ("on", "in", "and", "while", "during"))
    return False
