"""People said by a hyphened word whose first part is a function word (round 40): "three or four anxious
in-laws in ICU", "two no-shows in the cafeteria", "on-lookers by the fountain", "in-patients in the day
room". The tokenizer splits them at the hyphen and the parser takes "in" / "on" / "by" for a preposition
and "no" for a determiner, so the people and their place were lost ("in-laws in ICU" read nobody, only a
start). Before parsing, the word is said as its singular before "people" ("in-law people"), a compound
the reader knows is people; a relative by marriage after a kin word ("sister-in-law") is read elsewhere
(language/hyphened_people.py) and comes first."""

from __future__ import annotations

import re

# The function word first, then a person-like plural: "in-laws", "no-shows", "on-lookers", "has-beens",
# "in-patients", "by-standers", "up-and-comers" is left (three parts).
_WORD = re.compile(r"(?<![\w-])(in|on|by|no|has|up|off|out|over|down)-([a-z]*?(?:er|ee|ant|ent|ist|or|law|show|been|comer))s"
                   r"(?![\w-])", re.IGNORECASE)


def with_function_word_people(text: str) -> str:
    """The text with a hyphened person word led by a function word said as "<word> people"."""
    return _WORD.sub(lambda m: f"{m.group(1)}-{m.group(2)} people", text)
