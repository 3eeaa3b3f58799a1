"""Someone who only gives the signal, in a fronted time clause (round 52): "When the teacher claps,
twenty pupils walk to the hall", "Once the nurse calls out, two patients go in", "As soon as the guard
blows the whistle, ...". The clause says when the scene happens; the one who claps, calls or waves does
not move and is its moment, not one of its groups, when someone else is the subject after its comma
("..., she leads them out" keeps her: the pronoun is hers). The clause is left out before parsing, as a
finished act is (finished_acts.py); a clause whose subject moves ("When the doctor walks in, ...") is
kept."""

from __future__ import annotations

import re

from grove_tui.language.finished_acts import without_fronted

_ART = r"(?:the|a|his|her|their)"
_SIGNAL = (r"(?:claps?(?:\s+" + _ART + r"\s+hands)?|clapped(?:\s+" + _ART + r"\s+hands)?|"
           r"(?:blows?|blew)\s+" + _ART + r"\s+whistle|whistles?|whistled|(?:rings?|rang)\s+" + _ART + r"\s+bell|"
           r"(?:calls?|called)(?:\s+(?:out|time|last\s+orders))?|shouts?|shouted|(?:waves?|waved)(?:\s+them\s+(?:on|over|in|through))?|"
           r"nods?|nodded|(?:gives?|gave)\s+" + _ART + r"\s+(?:signal|nod|word|go-ahead)|"
           r"(?:stops?|stopped)(?:\s+(?:talking|speaking|playing))?|(?:says?|said)\s+(?:so|go))")
_FRONTED = re.compile(
    r"(?:^|(?<=[.;!?])\s+)(?:[Oo]nce|[Ww]hen|[Aa]s\s+soon\s+as)\s+(?P<who>(?:the|a|an|our|their|his|her)\s+"
    r"[^,.;!?]{1,30}?)\s+" + _SIGNAL + r"(?:\s+for\s+(?:the|a|an)\s+[a-z-]+)?,\s+(?=(?P<next>[A-Za-z]+))")


def without_signal_fronts(text: str) -> str:
    """The text without a fronted "When <someone> claps," clause (module doc)."""
    return without_fronted(text, _FRONTED)
