"""A request typed as chat (round 44): "can u add that + a busker near the cashpoint", "could you pls put
2 guards at the gate", "noodle bar q is like 8 deep rn". A polite question is the order it asks for ("add a
busker near the cashpoint"); "that" right after it is the thing just said, already in the scene; "like"
before a line's length is a filler ("like 8 deep": 8 deep; chat_lists.py leaves it out), "rn" and "atm" say "now". A queue said by its place
first and its length ("noodle bar q is 8 deep", "the tills queue's about 20 long") is that many people
queueing there ("8 people queue at the noodle bar")."""

from __future__ import annotations

import re

_ASKING = re.compile(r"(?P<comma>,\s*)?\b(?:can|could|would|will)\s+(?:u|you|ya|ye)\s+(?:(?:pls|plz|please|just|also|maybe)\s+)?"
                     r"(?P<verb>add|put|stick|place|have|include|pop|throw\s+in|chuck\s+in|drop)\b"
                     r"(?:\s+(?:that|this|those|these|them)\s*(?:\+|&|and|plus)\s*)?", re.IGNORECASE)
_PLACING = frozenset({"stick", "pop", "drop", "plonk", "chuck", "bung", "place"})
_NUMBER = r"(?:\d+|one|two|three|four|five|six|seven|eight|nine|ten|eleven|twelve|fifteen|twenty|thirty|forty|fifty)"
_NOW = re.compile(r"(?<=[a-z0-9])\s+(?:rn|atm|rite\s+now)\b(?=\s*(?:[,.;!?]|$))")
_PLACE_FIRST_QUEUE = re.compile(
    r"(^|[.,;!?]\s+)(?:the\s+)?(?P<place>(?:[A-Za-z][\w'-]*\s+){0,3}?[A-Za-z][\w'-]*)\s+(?:queue|q|line)\s*"
    r"(?:is|'s)\s+(?P<approx>(?:about|around|roughly|some|nearly|almost|over)\s+)?(?P<n>" + _NUMBER + r")\s+"
    r"(?:people\s+)?(?:deep|long|strong)\b", re.IGNORECASE)
_NOT_PLACES = frozenset({"the", "a", "this", "that", "our", "their", "his", "her", "its", "my", "your"})


def _order(m: re.Match[str]) -> str:
    """The order a request asks for; after a comma, a sentence of its own ("..., can u add" -> ". Add")."""
    said = " ".join(m.group("verb").lower().split())
    said = "put" if said in _PLACING else said  # "stick a guard by ...": placed, as placing_verbs.py writes it
    verb = said + (" " if m.group(0)[-1:].isspace() else "")
    return f". {verb[:1].upper()}{verb[1:]}" if m.group("comma") else verb


def as_chat_request(text: str) -> str:
    """The text with a chat request said as its order, and a place-first queue as its people (module doc)."""
    text = _NOW.sub("", text)
    text = _ASKING.sub(_order, text)

    def queue(m: re.Match[str]) -> str:
        place = m.group("place")
        if place.split()[0].lower() in _NOT_PLACES:
            return m.group(0)
        said = f"{(m.group('approx') or '').strip()} {m.group('n')} people queue at the {place}".strip()
        if not m.group(1).strip() or m.group(1).strip() in ".!?":
            said = said[:1].upper() + said[1:]
        return f"{m.group(1)}{said}"
    return _PLACE_FIRST_QUEUE.sub(queue, text)
