"""Chat items that name a place, then a meeting, then its head count: "boardroom mtg 9 ppl", "kitchen
standup 6 people", "meeting in lab 2, 4 ppl". The item is written out as its people meeting in that place
("9 people meeting in boardroom"), as when typed that way: otherwise the count sits after a noun phrase
("boardroom meeting") that is no verb, and the people and their place fall apart. An item whose first words
hold a preposition, a verb or a person ("3 devs at the desk") is left alone.
"""

from __future__ import annotations

import re

from grove_tui.language.lexicon import PERSON_NOUNS
from grove_tui.language.tokens import lemma

# The nouns of a gathering that chat puts after its place.
_MEETING = r"(?:meeting|meetings|standup|stand-up|huddle|briefing|catch-up|catchup|call|sync|workshop|review)"
# A head count: a figure or a small number word, with "about" or not; then people.
_COUNT = (r"(?:(?:about|around|roughly|approx\.?|~)\s*)?(?:\d{1,4}|two|three|four|five|six|seven|eight|nine|ten|"
          r"eleven|twelve|fifteen|twenty|thirty|a dozen)")
_PEOPLE = r"(?:people|persons|attendees|heads)"
_END = r"(?=\s*(?:[,;.!]|$))"
# "<place> <meeting> <count> people"
_PLACE_FIRST = re.compile(rf"(?:^|(?<=[,;:]))(\s*)([A-Za-z][A-Za-z0-9' -]{{1,40}}?)\s+{_MEETING}\s*[,:(-]?\s*"
                          rf"({_COUNT}\s+{_PEOPLE})\)?{_END}", re.IGNORECASE)
# "<meeting> in <place>[,] <count> people"
_MEETING_FIRST = re.compile(rf"(?:^|(?<=[,;:]))(\s*){_MEETING}\s+(in|at)\s+([A-Za-z][A-Za-z0-9' -]{{1,40}}?)"
                            rf"\s*[,:(-]?\s*({_COUNT}\s+{_PEOPLE})\)?{_END}", re.IGNORECASE)
# Words that make the item's head more than a bare place name.
_NOT_BARE = frozenset("in at on by to from into near inside outside with is are was were has have and the a an "
                      "for of".split())


def with_chat_meetings(text: str) -> str:
    """The text with each chat item "<place> meeting <N> people" as "<N> people meeting in <place>"."""
    return _MEETING_FIRST.sub(_meeting_first, _PLACE_FIRST.sub(_place_first, text))


def _bare_place(words: list[str]) -> bool:
    return 1 <= len(words) <= 5 and not set(words) & _NOT_BARE and \
        not any(lemma(w) in PERSON_NOUNS or w in ("people", "persons") for w in words)


def _place_first(m: re.Match[str]) -> str:
    lead, place, count = m.group(1), m.group(2).strip(), m.group(3)
    words = place.lower().split()
    if not _bare_place(words):
        return m.group(0)
    return f"{lead}{count} meeting in {place}"


def _meeting_first(m: re.Match[str]) -> str:
    lead, prep, place, count = m.group(1), m.group(2), m.group(3).strip(), m.group(4)
    words = place.lower().split()
    if not 1 <= len(words) <= 5 or any(lemma(w) in PERSON_NOUNS for w in words):
        return m.group(0)
    return f"{lead}{count} meeting {prep} {place}"
