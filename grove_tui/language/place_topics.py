"""A place that heads a line as its topic, the way people jot a scene down: "platform 2 rn: 20 people
waiting", "sports hall right now - 30 kids playing", "food court at the moment... about 40 shoppers":
a bare place phrase, a word or two of time, then a colon, a dash or dots; the people after it are
there (language/clauses.py reads the sentence's scene with it)."""

from __future__ import annotations

from grove_tui.language.place_names import CHAT_TIME_WORDS, TIME_WORDS
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
        if s.low[j] == "(" and (close := next((x for x in range(j + 1, min(j + 6, s.n)) if s.low[x].startswith(")")), None)):
            j = close + 1  # "platform 2 (rush hour): ..."
            if s.low[close] != ")":
                return close < s.n - 1  # "(rush hour):" read as one mark
            continue
        if s.low[j] in _TIME_SINGLE or s.low[j] in CHAT_TIME_WORDS or s.low[j] in TIME_WORDS:
            j, timed = j + 1, True
            continue
        break
    while j + 1 < s.n and s.low[j] == s.low[j + 1] and s.low[j] in _TOPIC_MARKS:
        j += 1  # ">>", "--"
    mark = s.low[j] if j < s.n else ""
    return j + 1 < s.n and (mark in _TOPIC_MARKS or mark.strip(")") in _TOPIC_MARKS or (timed and mark == ",")) \
        and not s.hyphen_inside(j)
