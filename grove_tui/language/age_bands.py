"""People said by an age band (round 44): "Eighteen over-fifties are seated in the waiting area", "a
dozen under-fives play in the soft play", "two over-60s wait", "a few twenty-somethings". The band is a
plural noun for people no list has, and the parser splits it ("over", "-", "fifties"), so the count and
the people were lost. Written before parsing as what the band says of them ("older people", "young
children", "young people"), it is read as any counted plural. A band that names a club, class or
session ("the over-60s club", "the under-12s team") or a room kept for it ("the under-twos room") is
left as it is."""

from __future__ import annotations

import re

_DECADES = {"twenties": 20, "thirties": 30, "forties": 40, "fifties": 50, "sixties": 60, "seventies": 70,
            "eighties": 80, "nineties": 90}
_SMALL = {"ones": 1, "twos": 2, "threes": 3, "fours": 4, "fives": 5, "sixes": 6, "sevens": 7, "eights": 8,
          "nines": 9, "tens": 10, "elevens": 11, "twelves": 12, "thirteens": 13, "fourteens": 14, "fifteens": 15,
          "sixteens": 16, "seventeens": 17, "eighteens": 18}
_AGES = "|".join(sorted([*_DECADES, *_SMALL], key=len, reverse=True))
# A band in words ("over-fifties", "under fives") or in digits with its hyphen ("over-60s", "under-12s"; "for over
# 10s" is a time).
_BAND = re.compile(r"\b(over|under)(?:\s*-?\s*(" + _AGES + r")|\s*-\s*(\d{1,2})'?s)\b(?!\s*-)(?=\s*(\w*))",
                   re.IGNORECASE)
_SOMETHINGS = re.compile(r"\b(?:twenty|thirty|forty|fifty)\s*-?\s*somethings\b", re.IGNORECASE)
# Words after a band that make it the name of what they belong to or go to.
_NAMED = frozenset("club clubs class classes session sessions group groups team teams squad squads swim night "
                   "nights morning mornings lunch lunches section league match game disco rail railcard "
                   "discount rate ticket tickets "
                   # a room or area kept for the band ("the under-twos room", "the under-fives area"; round 69)
                   "room rooms area areas zone zones corner unit ward bay pool playground garden toilets "
                   "loos changing nest den space".split())


def _age(word: str) -> int | None:
    low = word.lower().replace("'", "")
    if low in _DECADES:
        return _DECADES[low]
    if low in _SMALL:
        return _SMALL[low]
    return int(low[:-1]) if low[:-1].isdigit() else None


def _band(m: re.Match[str]) -> str:
    if m.group(4).lower() in _NAMED or m.string[:m.start()].lower().rstrip().endswith("of the"):
        return m.group(0)  # "the over-60s club", "a coach of the under-12s": what they belong to
    age = _age(m.group(2) or f"{m.group(3)}s")
    if age is None:
        return m.group(0)
    if m.group(1).lower() == "over":
        return "older people" if age >= 40 else "people"
    return "young children" if age <= 12 else "young people"


def with_age_bands(text: str) -> str:
    """The text with each age band written as what it says of the people (module doc)."""
    return _SOMETHINGS.sub("young people", _BAND.sub(_band, text))
