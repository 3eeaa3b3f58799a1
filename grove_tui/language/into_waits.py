"""A stay said by how far into it the sentence is (round 49): "Forty minutes into his wait in outpatients,
an older gentleman heads to the pharmacy", "Twenty minutes into their break in the staff room, two nurses
go back to ward A", "an hour into the queue at the desk". The length is before "into" and the stay is a
noun after an owner, so no stay is read. Said as the length and what is done ("After forty minutes
waiting in outpatients, ...", as `hyphened_waits` says a hyphened length), it is the stay the people make
where they are before the sentence's verb."""

from __future__ import annotations

import re

from grove_tui.language.hyphened_waits import _DOING, _LENGTH

_UNIT = r"(?P<unit>seconds?|secs?|minutes?|mins?|hours?)"
_INTO = re.compile(r"(?:(?<=^)|(?<=[.;!?]\s)|(?<=,\s))" + _LENGTH.replace("(?P<n>", "(?P<n>an?|") + r"\s+" + _UNIT +
                   r"\s+into\s+(?:his|her|their|its|the|a|my|our|your)\s+(?:(?:long|short|tedious|boring)\s+)?"
                   r"(?P<what>" + "|".join(sorted(_DOING, key=len, reverse=True)) + r")\b", re.IGNORECASE)
_UNITS = {"sec": "seconds", "second": "seconds", "min": "minutes", "minute": "minutes", "hour": "hours"}


def with_stays_into(text: str) -> str:
    """The text with "forty minutes into his wait" said as "after forty minutes waiting" (module doc)."""
    def said(m: re.Match[str]) -> str:
        n = m.group("n").lower()
        if n == "half":
            return m.group(0)  # "half hour into": no length said so
        unit = m.group("unit").lower().rstrip("s")
        one = n in ("a", "an", "one", "1")
        length = f"{'one' if n in ('a', 'an') else n} {_UNITS[unit] if not one else _UNITS[unit][:-1]}"
        after = "After" if m.start() == 0 or text[:m.start()].rstrip()[-1:] in ".;!?" else "after"
        return f"{after} {length} {_DOING[m.group('what').lower()]}"
    return _INTO.sub(said, text)
