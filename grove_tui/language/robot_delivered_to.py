"""The robot bringing something out to a person named with a clause of where they are (round 57):
"the robot carries a tray out to Grandad, who is dozing in the conservatory", "the robot wheels the
post over to the receptionist, who's sorting files at the front desk". The person is at that place and
the robot goes there: without this the place was read as a place the robot passes and the person had
none. The sentence is said again as the robot's errand to the place and the person's own clause:
"the robot carries a tray out to the conservatory, and Grandad is dozing in the conservatory".
"""

from __future__ import annotations

import re

_VERBS = r"(?:brings|takes|carries|fetches|delivers|wheels|ferries|returns|hands|passes|runs|drives|rolls|trundles)"
_PERSON = (r"(?:(?:my|our|his|her|their|the|a|an) [a-z][a-z-]*(?: [a-z][a-z-]*)?"
           r"|(?:(?:Mr|Mrs|Ms|Miss|Dr|Auntie|Aunt|Uncle|Grandma|Grandad|Granny|Grandpa|Nan) )?[A-Z][a-z]+)")
_PLACE = r"(?:the|a|an|her|his|their|our|my) [a-z][^,.;!?]*?"
_TO = re.compile(
    r"(?P<pre>\b(?:the|The) robot (?:[a-z]+ly )?" + _VERBS + r"\b[^.;!?]*?\b(?:(?:out|over|across|up|down|back|round|along) )?to) "
    r"(?P<person>" + _PERSON + r"), who(?:'s| is| are|'re) (?P<doing>[a-z]+ing(?: [a-z]+){0,2}?) (?P<prep>on|in|at|by|near|beside) "
    r"(?P<place>" + _PLACE + r")(?=[,.;!?]|$| and | while | as )")


def _said_again(m: re.Match[str]) -> str:
    return (f"{m.group('pre')} {m.group('place')}, and {m.group('person')} is {m.group('doing')} "
            f"{m.group('prep')} {m.group('place')}")


def as_delivered_to(text: str) -> str:
    """The text with "... to X, who is <doing> on Y" said as the robot going to Y and X <doing> there."""
    return _TO.sub(_said_again, text)
