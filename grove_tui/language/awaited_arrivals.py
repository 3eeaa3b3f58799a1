"""People said to come only later, in a fronted time clause (round 37): "Before the first patient
arrives, Karen pops out to reception", "Before the shoppers arrive, two cleaners mop the food court",
"Before the boss gets in, Dave nips ...". The clause sets when the scene happens; those who arrive
after it are not in it, so the clause is no group of the scene. It is left out before parsing when
someone else is the subject of the sentence after its comma."""

from __future__ import annotations

import re

_ARRIVING = (r"(?:arrives?|arriving|gets? (?:in|here|there)|comes? (?:in|down|back)|turns? up|shows? up|"
             r"walks? in|rolls? in|wakes? up|gets? back)")
_FRONTED = re.compile(r"(?:^|(?<=[.;!?])\s+)(?:[Bb]efore|[Aa]head of when) (?:the|a|an|any|our|their|his|her|"
                      r"my|some|all the)\b[^,.;!?]{1,40}? " + _ARRIVING + r",\s+(?=[A-Za-z])")


def without_awaited_arrivals(text: str) -> str:
    """The text without a fronted "Before <people> arrive," clause (module doc)."""
    out: list[str] = []
    at = 0
    for m in _FRONTED.finditer(text):
        out.append(text[at:m.start()] + (" " if m.start() > 0 else ""))
        nxt = m.end()
        out.append(text[nxt:nxt + 1].upper())
        at = nxt + 1
    out.append(text[at:])
    return "".join(out)
