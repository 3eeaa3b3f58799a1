"""A vehicle's news typed as a chat heading (round 66): "coach running late: ~25 ppl waitin @ stand
4", "train delayed - 12 ppl on platform 2", "Flight cancelled! 30 ppl at gate A1". The heading says why
people wait; it names no one. A coach is also a person's job (a football coach), so the heading
would be read as a coach walking; it is dropped before the people after it are read. A comma is no
heading's stop: "The coach is late, so he runs to the pitch" is a person."""

from __future__ import annotations

import re

_VEHICLES = "coach|bus|train|tram|flight|plane|ferry|shuttle|boat|minibus|taxi|cab"
_STATUS = r"running\s+late|late|delayed|cancell?ed|canceled|held\s+up|stuck|diverted|overdue|broken\s+down"
_HEADING = re.compile(
    rf"^\s*(?:(?:the|our|my|a|this)\s+)?(?:[\d.:]+\s*(?:am|pm)?\s+)?(?:{_VEHICLES})(?:\s+(?:{_VEHICLES}))?"
    rf"(?:\s+[A-Za-z]?\d+[A-Za-z]?)?"
    rf"\s+(?:is\s+|'s\s+|’s\s+)?(?:{_STATUS})(?:\s+(?:by\s+|again\s+)?(?:~|about\s+)?\d+\s*[a-z]*)?\s*"
    r"(?::|-|–|—|!)\s+(?=\S)", re.IGNORECASE)


def without_vehicle_headings(text: str) -> str:
    """The text without a vehicle's news before a chat's colon, dash or '!' (see the module doc)."""
    return _HEADING.sub("", text, count=1)
