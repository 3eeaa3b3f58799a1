"""A second verbless chat item of one person joined by "and" or a comma after an "-ing" item: "2 people
queuing at pharmacy and a cleaner loitering by the lifts", "three kids splashing in the shallows, a
lifeguard pacing by the steps". Without a verb the parser may read a person word that is also an
adjective or a verb ("cleaner", "guard", "nurse") as a modifier of the "-ing" word taken as a noun, and
the person is dropped (with the first item's verb lost with them). The item is written with its "is":
"and a cleaner is loitering by the lifts". Only after an earlier "-ing" item of the same sentence, only
for a person word, and only when a place word ("at", "by", "near" ...) follows the "-ing" word."""

from __future__ import annotations

import re

from grove_tui.language.chat_fragments import ING_NOUNS, person_word

_JOINED = re.compile(r"(\s+and\s+|,\s*|;\s*)(a|an|one|1|the)\s+([a-z]+)\s+(?=([a-z]{3,}ing)\s+"
                     r"(?:at|by|near|in|on|outside|inside|beside|behind|around|next|under|along|@)\b)", re.IGNORECASE)
_EARLIER_ING = re.compile(r"\b[a-z]{3,}ing\b", re.IGNORECASE)


def with_joined_ing_items(text: str) -> str:
    """The text with each such joined one-person "-ing" item given its "is" (see the module doc)."""
    def joined(m: re.Match[str]) -> str:
        before = text[:m.start()]
        sentence = re.split(r"[.!?]\s", before)[-1]
        if m.group(4).lower() in ING_NOUNS or not person_word(m.group(3)) or \
                not any(w.group(0).lower() not in ING_NOUNS for w in _EARLIER_ING.finditer(sentence)):
            return m.group(0)
        return f"{m.group(1)}{m.group(2)} {m.group(3)} is "

    return _JOINED.sub(joined, text)
