"""A feeling fronted before a length of stay (round 65): "Fed up after thirty minutes in the waiting
room, a driver limps across to X", "Restless after an hour at the bar, two men wander off to Y". "After
N minutes in P, ..." is already read as a wait of N minutes at P before the move; the feeling before it
hides the time from that pass, and only says why they go. It is left out, so the sentence opens on the
length of stay ("After thirty minutes in the waiting room, a driver ..."). Only words of the language
that open no subject and are shaped as feelings are taken for one, so "Tom after ten minutes ..." keeps Tom."""

from __future__ import annotations

import re

from grove_tui.language.feeling_adjectives import FEELINGS
from grove_tui.language.parser import known_word

_UNIT = r"(?:minutes?|mins?|hours?|hrs?|seconds?|secs?|quarter\s+of\s+an\s+hour|half\s+an\s+hour|an\s+hour)"
_FRONTED = re.compile(r"^([A-Z][a-z]+(?:[\s-][a-z]+){0,3}?),?\s+(after\s+(?:(?:[\w-]+\s+){0,3}?" + _UNIT +
                      r"|half\s+an\s+hour|an\s+hour|a\s+quarter\s+of\s+an\s+hour)\b[^,.;!?]{0,80},\s)")
_NO_FEELING = frozenset("a an the two three four five six seven eight nine ten some several his her their our my "
                        "this that these those one everyone everybody someone somebody nobody he she they we i it "
                        "you all both each".split())


# Endings of words of feeling or state ("fed up", "restless", "fidgety", "anxious", "peckish", "impatient").
_ENDINGS = ("ed", "ing", "y", "less", "ful", "ous", "ish", "ive", "ent", "ant")


def _feeling(word: str) -> bool:
    """Whether the first word of a fronted phrase says a feeling or state, not a name ("Tom")."""
    return word in FEELINGS or word in ("sick", "glum", "cross", "done", "weary") or (
        len(word) >= 3 and word.endswith(_ENDINGS))


def without_feelings_before_stays(text: str) -> str:
    """The text with a feeling fronted before "after N minutes in P," left out (module doc)."""
    m = _FRONTED.match(text)
    if m is None:
        return text
    words = re.split(r"[\s-]+", m.group(1).lower())
    if words[0] in _NO_FEELING or not all(known_word(w) for w in words) or not _feeling(words[0]):
        return text
    rest = text[m.start(2):]
    return rest[:1].upper() + rest[1:]
