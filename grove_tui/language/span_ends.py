"""The end or start of a span said after a place preposition (round 51): "at the end of his session",
"towards the close of the shift", "by the end of her visit", "at the start of the appointment". The
noun after "of" is a time, no place, so nothing to refuse. A room's end is still a place: "at the end
of the corridor", "the far end of the platform" are headed by room words, never by a span."""

from __future__ import annotations

from grove_tui.language.event_names import EVENT_WORDS
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import lemma

# Parts of a span ("the end of", "the start of", "the rest of").
_PARTS = frozenset("end start beginning close middle rest remainder course finish last".split())
# Prepositions of time before the part ("at the end of", "towards the close of", "until the end of").
_TIME_PREPS = frozenset("at by towards toward until till after before for from near around about during "
                        "to".split())
# Spans beside the lexicon's events: stays, appointments, treatments and parts of the day or year.
_SPANS = EVENT_WORDS | frozenset("appointment treatment stay day week month year term semester holiday holidays "
                                 "weekend trip journey day-shift night-shift clinic round rounds surgery "
                                 "consultation check-up checkup dialysis visiting trading lunchtime".split())
_BEFORE_HEAD = frozenset("the a an his her their its our my your this that each every morning afternoon evening "
                         "night day late early first last long final whole".split())


def span_after_part(s: Sentence, k: int, prep: str, at: int) -> bool:
    """Whether the phrase from k after the preposition at `at` is a span of time whose part is said: the
    whole "the end of his session" after "at", or "his session" after its "of" (module doc)."""
    if prep in _TIME_PREPS and k + 2 < s.n and s.low[k] in ("the", "a", "its") and s.low[k + 1] in _PARTS and \
            s.low[k + 2] == "of":
        return _a_span(s, k + 3)
    if prep != "of" or at < 3 or s.low[at - 1] not in _PARTS:
        return False
    d = at - 2
    if s.low[d] not in ("the", "a", "its") or s.low[d - 1] not in _TIME_PREPS:
        return False
    return _a_span(s, k)


def _a_span(s: Sentence, k: int) -> bool:
    """Whether the phrase from k is headed by a span ("his session", "the morning shift"), no room."""
    j = k
    while j < s.n and s.low[j] in _BEFORE_HEAD and not (s.low[j] in _SPANS and (
            j + 1 >= s.n or s.w[j + 1].pos not in ("NOUN", "ADJ", "PROPN"))):
        j += 1
    return j < s.n and (s.low[j] in _SPANS or lemma(s.low[j]) in _SPANS) and \
        (j + 1 >= s.n or s.w[j + 1].pos not in ("NOUN", "PROPN"))  # not "the end of the day room"
