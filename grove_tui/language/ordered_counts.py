"""An order's first item said by a bare count and an "-ing" verb (round 34): "Have two waiting in the
lobby and three shoppers at the fountain", "Put three chatting at the station and a porter at the
door". `chat_people.py` writes "two people waiting" for a bare count after a comma or "and"; after a
sentence's "Have", "Get", "Put", "Keep" or "Leave" it does so only when a place's preposition or a
word of manner follows the "-ing" word ("Have two shopping bags ready" is a count of bags)."""

from __future__ import annotations

_ORDERS = frozenset("have get put keep leave".split())
_AFTER = frozenset("in at by on near round around outside inside beside behind next under over about along "
                   "together quietly patiently calmly nervously , and".split())


def ordered_before_a_place(lead: str, after: str) -> bool | None:
    """For a bare count led by `lead` and an "-ing" word followed by `after`: None when the lead is no
    order's verb, else whether a place's preposition or a word of manner follows."""
    words = lead.split()
    if not words or words[-1].lower() not in _ORDERS:
        return None
    return after.lower() in _AFTER
