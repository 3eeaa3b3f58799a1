"""Who sees to the people brought somewhere, said in a passive purpose (round 69): "a steward wheels a dizzy
fan out of the stand to be checked over by the medics at first aid", "walks a confused patient from
reception to be seen by the doctors in radiology". The doers of "to be checked over" are no group of the
scene (they were read as people waiting there, and the place was lost to the movers' route): the place
after them is where the people are taken. Said without them ("to be checked over at first aid"), the
place is the route's end and the purpose stays."""

from __future__ import annotations

import re

from grove_tui.language import lexicon as lx
from grove_tui.language.tokens import lemma

_SEEN_TO_BY = re.compile(
    r"\b(?P<purpose>to\s+(?:be|get)\s+(?:[a-z]+ly\s+)?[a-z]+(?:ed|en|wn|seen|t)"
    r"(?:\s+(?:over|after|to|at|up|out|down|through|on))?)\s+by\s+"
    r"(?P<doers>(?:the|a|an|some|two|three|their|his|her|our|one\s+of\s+the)\s+(?:[\w'-]+\s+){0,2}?(?P<head>[A-Za-z'-]+))"
    r"\s+(?P<prep>at|in|on|inside|by)\s+(?=\w)", re.IGNORECASE)


def without_seen_to_by(text: str) -> str:
    """The text without the people a passive purpose names before the place it is at (module doc)."""
    def said(m: re.Match[str]) -> str:
        head = m.group("head").lower()
        if lemma(head) not in lx.PERSON_NOUNS and head not in lx.PERSON_NOUNS and \
                not ("-" in head and head.endswith(("er", "ers"))):  # "a first-aider"
            return m.group(0)  # "to be collected by the van at the gate": no people
        return f"{m.group('purpose')} {m.group('prep')} "
    return _SEEN_TO_BY.sub(said, text)
