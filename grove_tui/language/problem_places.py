"""Going to where a problem is (round 31): "There's a double booking at the lane desk, so Gary comes down
from his office to sort it out", "A pipe has burst in the toilets and the caretaker hurries over to deal
with it", "a fight breaks out by the bar; two stewards run across to break it up". A clause before the
group's own says something is wrong at a place; the group goes with a purpose whose object points back
to it ("sort it out", "deal with it", "see to it", "fix the problem"), and with no destination of its own,
that place is where they go."""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import replace

from grove_tui.language.model import GroupReading
from grove_tui.language.places import PlaceIndex
from grove_tui.language.purposed_places import place_named

# A purpose whose object points back to the problem: "to sort it out", "to deal with it", "to see to
# things", "to fix the problem", "to break it up", "to clear up the mess", "to help".
_BACK = r"(?:it|this|that|them|things|the\s+(?:problem|issue|matter|mess|situation|spill|row|fight|fuss|trouble))"
_PURPOSE = re.compile(r"\bto\s+(?:(?:go|come|help)\s+(?:and\s+)?)?(?:sort|deal|see|fix|handle|break|clear|mop|clean|"
                      r"tidy|calm|settle|resolve|investigate|check|look|smooth|straighten|mediate|defuse|attend|"
                      r"help|assist|intervene|step)\w*\b(?:\s+(?:out|up|down|with|to|into|over|in|on))?"
                      r"(?:\s+" + _BACK + r"\b|\s+(?:out|up)\b|(?=\s*[,.;]|\s*$))", re.I)
# Where the problem is, said before the group: "at the lane desk", "in the toilets", "by the bar".
_AT = re.compile(r"\b(?:at|in|on|by|near|outside|inside|beside)\s+((?:[\w'-]+\s*){1,4})", re.I)
_MOVING = re.compile(r"\b(?:come|came|go|went|head|hurr|rush|run|ran|dash|race|walk|nip|pop|stride|strode|march|"
                     r"make|made|mak|wander|stroll|sprint|jog|step|get|got|trot|scurr|bustle|storm|charg|descend|"
                     r"amble|traipse|troop|fly|flies|flew|zoom|shoot|shot|dart)\w*\b", re.I)


def problem_places(prompt: str, index: PlaceIndex, groups: Sequence[GroupReading]) -> tuple[GroupReading, ...]:
    """Groups that go, with no destination, to see to something said wrong at a place before them, go
    to that place."""
    out: list[GroupReading] = []
    for g in groups:
        at = prompt.find(g.text) if g.text else -1
        m = _PURPOSE.search(g.text) if g.intent == "walk" and g.destination is None and at > 0 else None
        if m is not None and _MOVING.search(g.text[:m.start()]):
            before = re.split(r"[.;!?]", prompt[:at])[-1]  # the same sentence only
            place = None
            for found in _AT.finditer(before):
                place = place_named(index, found.group(1).split()) or place
            if place is not None and place != g.start:
                g = replace(g, destination=place)
        out.append(g)
    return tuple(out)
