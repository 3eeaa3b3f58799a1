"""A time said by a bare "-ing" noun at the head of a sentence, with no comma (round 34): "After
pudding a carer walks Alastair to his bed", "Before training two coaches wait by the nets". The parser
reads the noun as a verb whose object is the person after it, so the person is lost. A comma after
the time keeps the person the subject; it is written so. Only nouns of an event or a part of the day
are read so ("After closing" is `TIME_NOUNS`' already; "After feeding the ducks, ..." is left alone:
a verb with its object)."""

from __future__ import annotations

import re

_ING_NOUNS = ("pudding", "training", "swimming", "bowling", "dancing", "singing", "evening", "morning",
              "briefing", "bingo", "shopping", "boarding", "landing", "kick-off", "christening", "fencing",
              "sailing", "skating", "climbing", "roll-call", "roll call", "evensong", "matins", "reading")
_FRONTED = re.compile(rf"(^|[.!?]\s+)((?:After|Before|During|Following)\s+(?:{'|'.join(_ING_NOUNS)}))"
                      r"(?=\s+(?:a|an|the|two|three|four|five|six|some|[A-Z][a-z]+)\b)")


def with_fronted_ing_times(text: str) -> str:
    """The text with a comma after a fronted time said by a bare "-ing" noun (module doc)."""
    return _FRONTED.sub(lambda m: f"{m.group(1)}{m.group(2)},", text)
