"""Leaving a room said by shutting its door behind one (round 72): "Sandra pulls her office door to and
cuts across the dock", "the caretaker locks the boiler room door behind him and heads for the hall", "two
clerks shut the office door and go down to the canteen". Closing a room's door and then going somewhere
is leaving that room: said as "leaves her office and ...", so the room (an owner's office by its owner)
is the start."""

from __future__ import annotations

import re

_CLOSED = re.compile(
    r"\b(?P<verb>(?:pull|shut|close|lock|push|bang|slam)(?:s|es|ed|d|ing)?|shutting|slamming)\s+"
    r"(?P<det>her|his|their|my|our|the)\s+(?P<room>(?:[a-z'’-]+\s+){0,2}?[a-z'’-]+)\s+doors?"
    r"(?:\s+(?:to|shut|closed|behind\s+(?:her|him|them|me|us|herself|himself|themselves)))?"
    r"(?=\s*,?\s+(?:and|then)\s)", re.I)
# Last words of a room whose door is shut behind one (never "the car door", "the fridge door").
_ROOMS = frozenset("office room study lab laboratory studio workshop kitchen shop store storeroom stockroom cabin "
                   "cupboard ward suite lounge hall classroom library surgery booth den vestry chapel gallery "
                   "bedroom bathroom cellar basement garage shed".split())
_LEAVE = {"s": "leaves", "es": "leaves", "ed": "left", "d": "left", "ing": "leaving", "": "leave"}


def as_left_behind_door(text: str) -> str:
    """The text with "pulls her office door to and ..." said as "leaves her office and ..."."""
    def said(m: re.Match[str]) -> str:
        if m.group("room").lower().split()[-1] not in _ROOMS:
            return m.group(0)
        verb = m.group("verb").lower()
        stem = re.match(r"(pull|shut|close|lock|push|bang|slam)", verb)
        end = verb[len(stem.group(1)):] if stem else ""
        end = "ing" if end.endswith("ing") else end.lstrip("t").lstrip("m") if end not in _LEAVE else end
        return f"{_LEAVE.get(end, 'leaves')} {m.group('det')} {m.group('room')}"
    return _CLOSED.sub(said, text)
