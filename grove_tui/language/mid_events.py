"""A time said by "mid-" and an event noun (round 39): "Mid-party, the JCR's smoke detector trips ...",
"In mid-tour, the visitors ...", "... wander to the café mid-tour". The hyphen leaves the noun a word of
its own, and "party", "tour", "class" also name a group of people, so the time was read as one more
group (with no start, or the start taken from the real group). "Midway through the party" is read as a
time already; the text is written so. Only nouns of an event are read so: "mid-sized", "mid-range",
"mid-level" are adjectives and left alone."""

from __future__ import annotations

import re

_EVENT_NOUNS = ("party", "parties", "tour", "class", "lesson", "meeting", "match", "game", "show", "session",
                "shift", "gig", "concert", "lecture", "service", "wedding", "rehearsal", "performance",
                "film", "movie", "seminar", "tutorial", "briefing", "ceremony", "speech", "set", "service",
                "round", "race", "practice", "disco", "screening", "talk", "visit", "workout", "drill")
_MID = re.compile(rf"\b(?:([Ii])n\s+)?([Mm])id-({'|'.join(sorted(set(_EVENT_NOUNS), key=len, reverse=True))})\b"
                  r"(?!-)")


def with_mid_events(text: str) -> str:
    """The text with "mid-party" written "midway through the party" (module doc)."""
    return _MID.sub(lambda m: f"{'M' if m.group(1) == 'I' else m.group(2)}idway through the {m.group(3)}", text)
