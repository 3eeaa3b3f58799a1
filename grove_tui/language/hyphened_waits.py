"""A stay said as a noun with its length before it (round 44): "After a fifteen-minute wait in the
observation area, a teenager heads for the exit", "Following a 20-minute break in the staff room, two
nurses go back to ward A", "after a half-hour sit on the benches". The length is a hyphened adjective of
"wait", "break", "rest" or the like, so no number of minutes is read and the stay is lost. Said as the
length and what is done ("After fifteen minutes waiting in the observation area, ..."), it is the stay
the people make where they are before the sentence's verb, as "After ten minutes in the sauna" is."""

from __future__ import annotations

import re

_UNITS = {"second": "seconds", "sec": "seconds", "minute": "minutes", "min": "minutes", "hour": "hours"}
_DOING = {"wait": "waiting", "stay": "staying", "sit": "sitting", "sit-down": "sitting", "rest": "resting",
          "break": "resting", "breather": "resting", "pause": "waiting", "queue": "queueing", "natter": "chatting",
          "chat": "chatting", "nap": "napping", "snooze": "snoozing", "coffee": "sitting", "cuppa": "sitting"}
_LENGTH = (r"(?P<n>\d+|one|two|three|four|five|six|seven|eight|nine|ten|eleven|twelve|fifteen|twenty|"
           r"twenty-five|thirty|forty|forty-five|fifty|sixty|ninety|half)")
_STAY = re.compile(
    r"\b(?P<after>after|following)\s+(?:a|an)\s+(?:(?:long|short|quick|brief|tedious|boring)\s+)?" + _LENGTH +
    r"[-\s](?P<unit>second|sec|minute|min|hour)\s+(?P<what>" + "|".join(sorted(_DOING, key=len, reverse=True)) +
    r")\b", re.IGNORECASE)


def with_stays_as_lengths(text: str) -> str:
    """The text with "after a fifteen-minute wait" said as "after fifteen minutes waiting" (module doc)."""
    def said(m: re.Match[str]) -> str:
        n, unit = m.group("n"), m.group("unit").lower()
        length = "half an hour" if n.lower() == "half" and unit == "hour" else \
            f"{n} {_UNITS[unit] if n.lower() not in ('one', '1') else unit}"
        after = "After" if m.group("after")[:1].isupper() else "after"  # "following" as "after": the stay comes first
        return f"{after} {length} {_DOING[m.group('what').lower()]}"
    return _STAY.sub(said, text)
