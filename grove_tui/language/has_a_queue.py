"""A queue said as something a place has (round 44): "toy shop till has a line of 3, security guy stood
near info desk", "the pharmacy counter has a queue of about ten", "The café has a long line of 12
people". The place was read as the sentence's scene and the queue's own clause took the next group's
place; said as the people queueing there ("3 people queue at toy shop till"), the queue is at its
place whatever is said after it."""

from __future__ import annotations

import re

from grove_tui.language.queue_lengths import _APPROX, _NUMBER

_HAS_A_QUEUE = re.compile(
    r"(?P<lead>^|[.!?;:,]\s+|\band\s+)(?P<place>(?:[Tt]he\s+)?[A-Za-z][\w'&-]*(?:\s+[A-Za-z0-9][\w'&-]*){0,4}?)\s+"
    r"(?:has|had|'s\s+got|has\s+got)\s+(?:a|an)\s+(?:long\s+|short\s+|small\s+|big\s+|growing\s+)?(?:queue|line)\s+of\s+"
    r"(?P<approx>" + _APPROX + r"\s+)?(?P<n>" + _NUMBER + r")(?:\s+(?P<who>people|persons|customers|shoppers|"
    r"passengers|patients|visitors|kids|children|parents|fans|diners|punters))?\b", re.IGNORECASE)


def with_queues_had(text: str) -> str:
    """The text with "<place> has a queue of N" said as "N people queue at <place>"."""
    def said(m: re.Match[str]) -> str:
        place = m.group("place")
        place = "the" + place[3:] if place.startswith("The ") else place
        if place.split()[0].lower() in ("she", "he", "it", "they", "there", "everyone", "nobody", "someone"):
            return m.group(0)
        who = m.group("who") or "people"
        return f"{m.group('lead')}{m.group('approx') or ''}{m.group('n')} {who} queue at {place}"
    return _HAS_A_QUEUE.sub(said, text)
