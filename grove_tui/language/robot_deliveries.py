"""The robot bringing something to a person where that person is (round 27): "The robot brings Nan's
pills over from the dining table to the settee where she's sitting", "the robot takes Mr Jones his tea
to the lounge, where he is dozing", "the robot carries a patient's notes to the ward where she waits".
The owner of what is carried is no one the robot leads: they are already where it goes, waiting there.
The sentence is said again with the thing carried on its own and the owner in a clause of their own:
"The robot brings the pills over from the dining table to the settee, and Nan waits at the settee."

So too a person the robot carries something out to, named with a clause of where they are (round 57: "the robot
carries a tray out to Grandad, who is dozing in the conservatory"): without it the place was read as one the robot
passes and the person had none. Said again as "the robot carries a tray out to the conservatory, and Grandad is
dozing in the conservatory".
"""

from __future__ import annotations

import re

_VERBS = r"(?:brings|takes|carries|fetches|delivers|wheels|ferries|returns|hands|passes)"
_OWNER = r"(?:(?:Mr|Mrs|Ms|Miss|Dr|Auntie|Aunt|Uncle|Grandma|Grandad|Granny|Grandpa) )?[A-Z][a-z]+|(?:the|a|an) [a-z]+"
_PLACE = r"(?:the|a|an|her|his|their|our|my) [^,.;!?]+?"
_WHERE = r",? where (?P<pro>she|he|they)(?:'s| is|'re| are|) ?(?P<doing>[a-z]+)[^.;!?]*"
# "the robot brings Nan's pills ... to the settee where she's sitting"
_OWNED = re.compile(r"(?P<pre>\b(?:the|The) robot (?:[a-z]+ly )?" + _VERBS + r") (?P<owner>" + _OWNER + r")'s? "
                    r"(?P<rest>[^.;!?]*?\b(?:to|into|over to) (?P<place>" + _PLACE + r"))" + _WHERE)
# "the robot brings Grandad his slippers ... to the sofa where he's dozing"
_GIVEN = re.compile(r"(?P<pre>\b(?:the|The) robot (?:[a-z]+ly )?" + _VERBS + r") (?P<owner>" + _OWNER + r") "
                    r"(?P<poss>his|her|their) (?P<rest>[^.;!?]*?\b(?:to|into|over to) (?P<place>" + _PLACE + r"))"
                    + _WHERE)


# "the robot carries soup out to Gran, who is knitting on the terrace" (a wider set of verbs: "runs", "trundles")
_TO_VERBS = r"(?:brings|takes|carries|fetches|delivers|wheels|ferries|returns|hands|passes|runs|drives|rolls|trundles)"
_PERSON = (r"(?:(?:my|our|his|her|their|the|a|an) [a-z][a-z-]*(?: [a-z][a-z-]*)?"
           r"|(?:(?:Mr|Mrs|Ms|Miss|Dr|Auntie|Aunt|Uncle|Grandma|Grandad|Granny|Grandpa|Nan) )?[A-Z][a-z]+)")
_TO_WHO = re.compile(
    r"(?P<pre>\b(?:the|The) robot (?:[a-z]+ly )?" + _TO_VERBS + r"\b[^.;!?]*?\b(?:(?:out|over|across|up|down|back|round|along) )?to) "
    r"(?P<person>" + _PERSON + r"), who(?:'s| is| are|'re) (?P<doing>[a-z]+ing(?: [a-z]+){0,2}?) (?P<prep>on|in|at|by|near|beside) "
    r"(?P<place>(?:the|a|an|her|his|their|our|my) [a-z][^,.;!?]*?)(?=[,.;!?]|$| and | while | as )")


def _said_again(m: re.Match[str], thing: str) -> str:
    owner = m.group("owner")
    waits = "wait" if m.group("pro") == "they" else "waits"
    return f"{m.group('pre')} {thing}{m.group('rest')}, and {owner} {waits} at {m.group('place')}"


def as_delivery(text: str) -> str:
    """The text with a delivery to someone where they are said as the robot's errand and their wait."""
    text = _OWNED.sub(lambda m: _said_again(m, "the "), text)
    text = _GIVEN.sub(lambda m: _said_again(m, m.group("poss") + " "), text)
    return _TO_WHO.sub(lambda m: f"{m.group('pre')} {m.group('place')}, and {m.group('person')} is {m.group('doing')} "
                                 f"{m.group('prep')} {m.group('place')}", text)
