"""Pass 2, a small part: words for people that name an event too ("the night shift", "the class",
"the tour"), read as a time when a word of time governs them ("After the night shift, two nurses
...", "at the end of the class"): no group of their own."""

from __future__ import annotations

import re

from grove_tui.language import lexicon as lx
from grove_tui.language.piling_out import moves_on
from grove_tui.language.sentence import Sentence

# Collectives that name an event too, after a word of time ("After the night shift, ...", "at the end of
# the class"): a time.
EVENT_COLLECTIVES = frozenset({"shift", "class", "tour"})
EVENT_TIME_WORDS = frozenset("after before during until till since end start beginning middle".split())
# Someone taken ill who is why a place is cleared ("cleared after a swimmer is sick"): the cause, no group.
CAUSE_WORDS = frozenset("after because when as since once".split())
ILLNESS_WORDS = frozenset("sick ill unwell injured hurt".split())
ILLNESS_VERBS = frozenset("faint collapse vomit".split())
CLEARING_VERBS = frozenset("clear evacuate empty close shut".split())


def event_after_time_word(s: Sentence, p: int, at: int) -> bool:
    """Whether the phrase at `at`, after the word at p, is an event named after a word of time: "after",
    "during", "until" or "the end of" before a collective that names an event too, with only
    determiners, adjectives and nouns between."""
    timed = s.low[p] in EVENT_TIME_WORDS or (s.low[p] == "of" and p > 0 and s.lemma(p - 1) in EVENT_TIME_WORDS)
    if not timed:
        return False
    end = next((k for k in range(at, min(at + 4, s.n)) if s.lemma(k) in EVENT_COLLECTIVES), None)
    return end is not None and all(s.w[k].pos in ("DET", "ADJ", "NOUN", "PRON") for k in range(at, end))


def cause_of_a_clearing(s: Sentence, p: int, at: int) -> bool:
    """Whether the person phrase at `at`, after the word at p, only says why a place is cleared: "The
    pool hall is cleared after a swimmer is sick in the water; everyone ... is sent out", "the café
    is evacuated after a visitor faints": the cause, not a group of the scene. A word of cause, then in
    its clause a word of being taken ill, after a verb of clearing in the same sentence."""
    if s.low[p] not in CAUSE_WORDS:
        return False
    end = at
    while end < s.n and not s.is_punct(end) and s.low[end] not in lx.CLAUSE_STARTERS - {"as"} and end < at + 8:
        end += 1
    taken_ill = any(s.low[k] in ILLNESS_WORDS or _base(s.low[k]) in ILLNESS_VERBS for k in range(at, end))
    sentence = s.w[p].sentence
    cleared = any(_base(s.low[k]) in CLEARING_VERBS for k in range(p) if s.w[k].sentence == sentence)
    return taken_ill and cleared


def _base(word: str) -> str:
    """A verb's base form by rule ("cleared", "faints", "evacuated", "collapses", "closed")."""
    for ending, cut in (("ied", "y"), ("ated", "ate"), ("osed", "ose"), ("ed", ""), ("es", "e"), ("s", "")):
        if word.endswith(ending) and len(word) >= len(ending) + 2:
            return word[: len(word) - len(ending)] + cut
    return word


# Events whose end empties a room as a matter of course ("the 9 am lecture ... empties out of LT1", "the
# matinee crowd spills out of the cinema"): the people leave, walking, unless something is urgent.
ROUTINE_EVENTS = frozenset("lecture seminar tutorial class lesson matinee screening film show performance concert "
                           "match game meeting service mass assembly talk session workshop".split())


def routine_emptying(s: Sentence, verb: int) -> bool:
    """Whether the subject of an emptying at `verb` is an event that ends as a matter of course: an
    event noun before it in its sentence ("The 9 am lecture, 120 first-years, empties out ...")."""
    return any(s.lemma(k) in ROUTINE_EVENTS and s.w[k].sentence == s.w[verb].sentence for k in range(verb))


def evacuating(s: Sentence, verb: int, pair: tuple[str, str], urgent: bool) -> bool:
    """Whether a phrasal verb of getting out at `verb` is an evacuation: "empty out" unless an event
    ends as a matter of course with nothing urgent, "get out" only when urgent."""
    if pair in lx.EVACUATION_PHRASES:
        return urgent or not (routine_emptying(s, verb) or moves_on(s, verb, pair))  # "piles out onto platform 1"
    return urgent


# "At 9 sharp", "by 7.30", "around noon", "at lunchtime": a clock time said before the subject.
_CLOCK_PREPOSITIONS = frozenset("at by around about after before from until till".split())
_CLOCK_TAILS = frozenset("sharp exactly precisely o'clock oclock am pm a.m. p.m. on the dot".split())
_CLOCK_WORDS = frozenset("noon midnight midday lunchtime teatime dawn dusk daybreak nightfall opening closing".split())
_CLOCK = re.compile(r"\d{1,2}([:.]\d\d)?(am|pm|h)?")


def after_a_clock_time(s: Sentence, at: int) -> bool:
    """Whether only a clock time stands between the start of a clause and `at` ("At 9 sharp a dozen staff
    stream in", "by 7.30 two porters wait ..."), so a subject may start there with no comma."""
    j = at - 1
    while j > 0 and s.low[j] in _CLOCK_TAILS:
        j -= 1
    if j < 1 or not (_CLOCK.fullmatch(s.low[j]) or s.low[j] in _CLOCK_WORDS or s.w[j].tag == "CD"):
        return False
    j -= 1
    if s.low[j] not in _CLOCK_PREPOSITIONS:
        return False
    return (j == 0 or s.is_punct(j - 1) or s.low[j - 1] in lx.CLAUSE_STARTERS) and \
        (s.low[at] in lx.DETERMINERS or s.w[at].pos == "NUM" or s.low[at] in lx.NUMBER_WORDS)
