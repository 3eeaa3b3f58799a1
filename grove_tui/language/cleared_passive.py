"""A zone cleared in the passive (round 30): "the sixty travellers stood there are cleared off it",
"the shoppers in the food court get cleared out of it", "everyone on the platform is cleared from it".
The people are moved out of where they are: they evacuate, starting from the place they were read at.
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import replace

from grove_tui.language.model import GroupReading

_CLEARED = re.compile(r"\b(?:is|are|was|were|be|been|being|get|gets|got|getting|gotten)\s+(?:\w+\s+)?"
                      r"(?:cleared|hustled|shooed|turfed|kicked|evacuated)\s+"
                      r"(?:off|out|out\s+of|from|away\s+from)\b", re.I)

# Cleared with no particle, the clause ending there (round 63): "everybody on the first platform, roughly
# 150 of them, is cleared", "the diners in the restaurant are evacuated and ...", "the crowd at the gate is
# moved on". "cleared to board" and "cleared through security" are passes, not an emptying: not read.
_CLEARED_BARE = re.compile(r"\b(?:is|are|was|were|get|gets|got|getting)\s+(?:(?:all|quickly|swiftly|promptly|"
                           r"immediately|then|soon|duly|calmly|hurriedly)\s+)?"
                           r"(?:cleared|evacuated|moved\s+on|moved\s+along|shooed\s+away|sent\s+away|ushered\s+out)"
                           r"(?=\s*(?:$|[.,;:!?]|\s(?:and|by|because|as|after|when|while|before|immediately|"
                           r"at\s+once|too|quickly|straight\s+away)\b))", re.I)


def cleared_away(groups: Sequence[GroupReading]) -> tuple[GroupReading, ...]:
    """Groups cleared off the place they wait at evacuate from it."""
    out: list[GroupReading] = []
    for g in groups:
        if g.intent == "wait" and g.location is not None and g.destination is None and (
                _CLEARED.search(g.text) or _CLEARED_BARE.search(g.text)):
            g = replace(g, intent="evacuate", start=g.location, location=None, wait_seconds=None)
        out.append(g)
    return tuple(out)
