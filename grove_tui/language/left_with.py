"""A thing left with someone's desk or at a counter (round 44): "a courier leaves a box with the community
desk", "a guest leaves her key at reception", "leaving a parcel at the front desk". To leave a thing
somewhere is to take it there: the verb of leaving took its object for the place left ("a box", refused
as a place the world lacks; "a parcel", the parcel shelves) and the desk for where the person was.
Read as dropping the thing off there, the desk is where the person goes; when the sentence goes on
("... and walks to the bar"), as handing it in there, the desk is where the next trip starts. One leaves "the café", never
"a café": only an object with "a", "an", "some" or a possessive is a thing, and only a place the world
names after "with" or "at" is where it is left; a person left ("leaves her son at the crèche") is
taken there too, and read the same way; "left" (a bag left by someone, language/event_causes.py) is
not touched."""

from __future__ import annotations

import re
from typing import TYPE_CHECKING

from grove_tui.language.tokens import lemma

if TYPE_CHECKING:
    from grove_tui.language.places import PlaceIndex

_LEFT_WITH = re.compile(
    r"\b(?P<verb>leaves|leave|leaving)\s+(?P<thing>(?:a|an|some|his|her|their|its|my|our)\s+(?:[A-Za-z][\w'-]*\s+){0,2}?"
    r"[A-Za-z][\w'-]*)\s+(?:with|at)\s+(?P<det>the|our|their)\s+(?P<place>[A-Za-z][\w'-]*)", re.IGNORECASE)
_DROPPING = {"leaves": "drops", "leave": "drop", "leaving": "dropping"}
_HANDING = {"leaves": "hands", "leave": "hand", "leaving": "handing"}
# The sentence goes on to another trip after the thing is left: "... and walks to the bar", "then heads".
_GOES_ON = re.compile(r"^[^.;!?]*\b(?:and|then)\s+(?:\w+\s+)?\w+(?:s|ed)\b", re.IGNORECASE)


def as_dropped_off(text: str, index: PlaceIndex) -> str:
    """The text with "leaves <a thing> with/at <a place>" said as "drops <it> off at <the place>"."""
    def drop(m: re.Match[str]) -> str:
        if not index.knows(lemma(m.group("place").lower())):
            return m.group(0)  # "leaves a note with the boss": no place of the world
        said = m.group("verb").lower()
        if _GOES_ON.match(text[m.end():]):
            return f"{_HANDING[said]} {m.group('thing')} in at {m.group('det')} {m.group('place')}"
        return f"{_DROPPING[said]} {m.group('thing')} off at {m.group('det')} {m.group('place')}"
    return _LEFT_WITH.sub(drop, text)
