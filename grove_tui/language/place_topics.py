"""A place that heads a line as its topic, the way people jot a scene down: "platform 2 rn: 20 people
waiting", "sports hall right now - 30 kids playing", "food court at the moment... about 40 shoppers":
a bare place phrase, a word or two of time, then a colon, a dash or dots; the people after it are
there (language/clauses.py reads the sentence's scene with it)."""

from __future__ import annotations

import re

from grove_tui.language.lexicon import NUMBER_WORDS
from grove_tui.language.place_names import CHAT_TIME_WORDS, TIME_NOUNS, TIME_WORDS
from grove_tui.language.sentence import Sentence

# What closes a topic: a colon, a dash between words (not a hyphen inside one), dots, a bar.
_TOPIC_MARKS = frozenset({":", "-", "—", "–", "...", "…", "|", ">", "->", "=>"})
# Words of time between the place and its mark: "rn", "right now", "at the moment", "atm", "this morning".
_TIME_RUNS = (("right", "now"), ("at", "the", "moment"), ("at", "present"), ("just", "now"),
              ("this", "morning"), ("this", "afternoon"), ("this", "evening"))
_TIME_SINGLE = frozenset({"atm", "rn", "currently", "now", "presently", "tonight", "today", "rush", "again",
                          "lol", "omg", "tbh", "pls", "plz"})


def topic_mark_at(s: Sentence, j: int) -> bool:
    """Whether the words from j, after a bare place phrase at the head of a sentence, close it as a
    topic: words of time (or none), then a colon, dash, dots or a bar, with words after it."""
    timed = False
    while j < s.n:
        run = next((r for r in _TIME_RUNS if tuple(s.low[j:j + len(r)]) == r), None)
        if run is not None:
            j, timed = j + len(run), True
            continue
        close = next((x for x in range(j + 1, min(j + 6, s.n)) if s.low[x].startswith(")")), None)
        if s.low[j] == "(" and close is not None:
            j = close + 1  # "platform 2 (rush hour): ..."
            if s.low[close] != ")":
                return close < s.n - 1  # "(rush hour):" read as one mark
            continue
        if s.low[j] == "," and not timed and j + 1 < s.n and _time_word(s.low[j + 1]):
            j += 1  # "the whale hall, sat afternoon: ...", "open plan, 9am: ..."
            continue
        if _time_word(s.low[j]) or (s.low[j] in ("at", "on", "by") and j + 1 < s.n and _time_word(s.low[j + 1])):
            j, timed = j + 1, True  # "rn", "9am", "at 5:30", "on sat"
            continue
        break
    while j + 1 < s.n and s.low[j] == s.low[j + 1] and s.low[j] in _TOPIC_MARKS:
        j += 1  # ">>", "--"
    mark = s.low[j] if j < s.n else ""
    counted = j + 1 < s.n and (s.low[j + 1].isdigit() or s.low[j + 1] in NUMBER_WORDS)  # "Gate A1, 25 people"
    return j + 1 < s.n and (mark in _TOPIC_MARKS or mark.strip(")") in _TOPIC_MARKS or
                            (mark == "," and (timed or counted))) and not s.hyphen_inside(j)


_DAYS = frozenset("monday tuesday wednesday thursday friday saturday sunday mon tue tues wed thu thur thurs fri sat "
                  "sun weekday weekend morning afternoon evening night lunchtime midday rush hour peak busy quiet "
                  "early late around about ~ am pm".split())


def _time_word(word: str) -> bool:
    """A word of a time said after a topic ("rn", "9am", "sat", "3:30pm", "evening rush")."""
    return word in _TIME_SINGLE or word in CHAT_TIME_WORDS or word in TIME_WORDS or word in TIME_NOUNS or \
        word in _DAYS or bool(re.fullmatch(r"\d{1,2}([:.]\d\d)?(am|pm)|\d{1,2}[:.]\d\d", word))
