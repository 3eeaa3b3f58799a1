"""Pass 2, a small part: words for people that name an event too ("the night shift", "the class",
"the tour"), read as a time when a word of time governs them ("After the night shift, two nurses
...", "at the end of the class"): no group of their own."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.sentence import Sentence


def event_after_time_word(s: Sentence, p: int, at: int) -> bool:
    """Whether the phrase at `at`, after the word at p, is an event named after a word of time: "after",
    "during", "until" or "the end of" before a collective that names an event too, with only
    determiners, adjectives and nouns between."""
    timed = s.low[p] in lx.EVENT_TIME_WORDS or (s.low[p] == "of" and p > 0 and s.lemma(p - 1) in lx.EVENT_TIME_WORDS)
    if not timed:
        return False
    end = next((k for k in range(at, min(at + 4, s.n)) if s.lemma(k) in lx.EVENT_COLLECTIVES), None)
    return end is not None and all(s.w[k].pos in ("DET", "ADJ", "NOUN", "PRON") for k in range(at, end))
