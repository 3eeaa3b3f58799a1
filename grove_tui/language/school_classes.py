"""A school class, form or team named by its number and said as the people themselves: "Year 4 and
year 5 walk to the hall", "Class 3 lines up in the playground", "Form 7B waits outside", "Team 2
heads to the pitch". With no count stated it is a whole class (a typical primary or secondary class,
vague) or a team; a count said with it ("Year 4, 28 pupils, ...") replaces it (mentions.py)."""

from __future__ import annotations

import re

from grove_tui.language import lexicon as lx
from grove_tui.language.counts import number_at
from grove_tui.language.mention import Mention
from grove_tui.language.model import Count
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import verb_lemma

# How many are in a class of a school year when the sentence does not say: a typical UK class.
CLASS_RANGE = (25, 30)
_SCHOOL_WORDS = frozenset({"year", "grade", "class", "form", "standard"})
_TEAM_WORDS = frozenset({"team", "squad"})
# Words after a year's number that name its class ("the Year 4 form", "the year 10 group").
_TAIL_WORDS = frozenset({"form", "class", "group", "set"})
_CODE = re.compile(r"^(\d{1,2})[a-z]?$")  # "7b", "10c", "4"
# Years and grades of a school run from reception (0) to 13; a bigger number is a calendar year or
# a room ("class 204"), no people.
_MAX_YEAR = 13


def _number(s: Sentence, i: int) -> tuple[int, int] | None:
    """(value, index after) of a class number at word i: "4", "four", "7B", "7 B"."""
    match = _CODE.match(s.low[i]) if i < s.n else None
    if match is not None:
        j = i + 1
        if j < s.n and len(s.low[j]) == 1 and s.low[j].isalpha() and s.low[j] not in ("a", "i") and \
                s.w[j].pos in ("PROPN", "NOUN", "X"):
            j += 1  # "Form 7 B"
        return int(match.group(1)), j
    return number_at(s, i)


def named_class(s: Sentence, at: int) -> Mention | None:
    """The class or team said at word `at` (after any article) by its word and number, when the
    people are the subject: a verb, "and", a comma or a bracket follows, not a noun ("year 6 pupils"
    are pupils, counted by their own words)."""
    if at + 1 >= s.n or s.low[at] not in _SCHOOL_WORDS | _TEAM_WORDS:
        return None
    if at > 0 and s.low[at - 1] in lx.PLACE_PREPOSITIONS | {"of", "from", "for", "to"}:
        return None  # "in year 4", "the teacher of class 3": where or whose, no group
    number = _number(s, at + 1)
    if number is None or not 0 <= number[0] <= _MAX_YEAR:
        return None
    end = number[1]
    if end < s.n and s.low[end] in _TAIL_WORDS and s.low[at] not in _TAIL_WORDS and \
            (end + 1 >= s.n or s.is_punct(end + 1) or s.w[end + 1].pos in ("VERB", "AUX")):
        end += 1  # "the Year 4 form, 26 youngsters, ...", "the year 10 group waits": the class by its word after
    if end < s.n and not (s.is_punct(end) or s.low[end] in ("and", "to") or s.w[end].pos in ("VERB", "AUX")
                          or s.w[end].tag in ("VBZ", "VBP", "VBD", "MD") or verb_lemma(s.low[end]) in lx.INTENT_VERBS):
        # ("Class 3 lines up": the small parser makes "lines" a noun)
        return None
    if s.low[at] in _TEAM_WORDS:
        low, high = lx.IMPLIED_RANGES["team"]
        label = "team"
    else:
        low, high = CLASS_RANGE
        label = "pupil"
    return Mention(at, end - 1, s.span(at, end - 1), label, Count("vague", s.choose(low, high, f"{at}:class"), low, high),
                   together=True)
