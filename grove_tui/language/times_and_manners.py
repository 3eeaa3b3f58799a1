"""A time or a manner after a place preposition, so nothing to refuse when the world lacks it (round 26):

- a day, a date or a span of the year: "on a sunny bank holiday Monday", "on Boxing Day", "on a wet
  Tuesday", "in the rush hour", "over the Easter weekend" (the phrase's head is a word of the calendar);
- a clock time: "at half past nine", "at quarter to ten", "at nine o'clock", "by 9.30";
- how people go: "on foot", "on tiptoe", "on crutches", "on their bikes", "by bike", "by bus", "in a hurry",
  "in single file", "in pairs"; round 69: "at the double", "at a trot", "at full tilt", and a thing held ready
  ("passports at the ready", "mops at hand"), and what people are busy in, said bare ("in induction", "in
  rehearsal", not "in the training room");
- round 54: the start or end of a span, "from first light", "since dawn", "until dusk", "from opening time",
  "until closing".
"""

from __future__ import annotations

import re

from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import lemma

_DAYS = frozenset("monday tuesday wednesday thursday friday saturday sunday weekday weekend day night eve holiday "
                  "morning afternoon evening lunchtime teatime dawn dusk daybreak nightfall midday midnight noon "
                  "hour fortnight week month year season term sunrise sunset sunup sundown daylight twilight "
                  "teatime suppertime bedtime".split())
# Heads that say a time only with a word before them ("first light", "opening time", "closing time").
_TIMED_HEADS = {"light": frozenset("first last".split()),
                "time": frozenset("opening closing lunch tea supper dinner bed kick-off kickoff feeding break "
                                  "home play nap start finish".split())}
# Bare words of a venue's hours after "from", "since", "until", "till" ("from opening", "until closing").
_HOURS_WORDS = frozenset("opening closing kick-off kickoff dawn dusk daybreak nightfall sunrise sunset "
                         "lunchtime teatime breakfast lunch".split())
_MONTHS = frozenset("january february march april may june july august september october november december".split())
_FEASTS = frozenset("christmas easter xmas diwali eid hanukkah halloween hallowe'en ramadan whitsun "
                    "michaelmas hogmanay".split())
_CLOCK_WORDS = frozenset("half quarter past to o'clock oclock am pm".split())
_NUMBERS = frozenset("one two three four five six seven eight nine ten eleven twelve twenty thirty".split())
# How people go, said after "on" ("on foot"), "by" ("by bike") or "in" ("in a hurry").
_ON_MANNER = frozenset("foot tiptoe tiptoes crutch crutches horseback bike bikes bicycle bicycles scooter scooters "
                       "skateboard skateboards skate skates rollerblades rollerskates stilts".split())
_BY_MANNER = frozenset("bike bicycle car bus coach train taxi cab tram boat ferry plane air road rail foot hand "
                       "scooter minibus van lorry tube metro underground chance mistake accident themselves "
                       "himself herself".split())
_IN_MANNER = frozenset("hurry rush panic huff daze dash flap frenzy trance single file pair pairs twos threes "
                       "fours silence tears uniform costume disguise convoy procession formation "
                       "tandem unison".split())
# What people are busy in, said bare after "in" ("six trainees in induction", "in rehearsal", "in session").
_IN_ACTIVITY = frozenset("induction training rehearsal session consultation conversation assessment orientation "
                         "detention treatment briefing debrief conference discussion prayer class".split())
# How people go or hold things, said after "at" ("at the double", "at a trot", "tickets at the ready").
_AT_MANNER = frozenset("ready double trot canter gallop jog sprint crawl speed pace haste leisure ease hand full "
                       "pelt".split())
_OWNERS = frozenset("a an the their his her my our your its".split())


def time_or_manner(s: Sentence, k: int, prep: str) -> bool:
    """Whether the phrase from word k, after the preposition `prep`, says a time or a manner (see the doc)."""
    low = s.low
    j = k
    while j < s.n and low[j] in _OWNERS:
        j += 1
    if j >= s.n:
        return False
    first = low[j]
    if prep == "on" and first in _ON_MANNER and (j + 1 >= s.n or not _a_place_noun_after(s, j)):
        return True  # "on foot", "on tiptoe", "on their bikes"
    if prep == "by" and j == k and first in _BY_MANNER and not _a_place_noun_after(s, j):
        return True  # "by bike", "by bus" (not "by the bus stop")
    if prep == "in" and first in _IN_MANNER:
        return True  # "in a hurry", "in single file", "in pairs"
    if prep == "in" and j == k and first in _IN_ACTIVITY and not _a_place_noun_after(s, j):
        return True  # "the academy has six trainees in induction": busy in it, no room "induction"
    if prep == "at" and first in _AT_MANNER and not _a_place_noun_after(s, j):
        return True  # "passports at the ready", "at the double", "at a trot", "at full tilt"
    if prep in ("at", "by", "around", "about", "after", "before", "until", "till") and _clock(s, k):
        return True  # "at half past nine", "by 9.30", "at ten o'clock"
    if prep in ("from", "since", "until", "till") and j == k and first in _HOURS_WORDS and \
            not _a_place_noun_after(s, j):
        return True  # "from opening", "until closing", "since dawn" (round 54)
    if prep in ("on", "in", "at", "during", "over", "for", "until", "till", "by", "after", "before", "around",
                "from", "since"):
        end = k
        while end < s.n and (s.w[end].pos in ("ADJ", "NOUN", "PROPN") or s.w[end].pos == "DET" and end == k or
                             low[end] in ("'s", "’s", "year's", "new")):
            end += 1
        if end > k:
            head = lemma(low[end - 1])
            words = {lemma(w) for w in low[k:end]}
            timed = head in _TIMED_HEADS and end - 2 >= k and low[end - 2] in _TIMED_HEADS[head]
            if timed or head in _DAYS or head in _MONTHS or head in _FEASTS or \
                    (words & _FEASTS and head in ("day", "eve")):
                return True  # "on a sunny bank holiday Monday", "on Boxing Day", "in the rush hour"
    return False


def _a_place_noun_after(s: Sentence, j: int) -> bool:
    """Whether a noun follows word j inside its phrase ("bike shed", "bus stop")."""
    return j + 1 < s.n and s.w[j + 1].pos in ("NOUN", "PROPN") and s.w[j + 1].tag != "VBZ" and \
        s.index.knows(lemma(s.low[j + 1])) and s.w[j].pos != "VERB"


def _clock(s: Sentence, k: int) -> bool:
    """Whether the words from k say a clock time ("half past nine", "quarter to ten", "9.30", "ten o'clock")."""
    low = s.low
    run = low[k:k + 4]
    if run and re.fullmatch(r"\d{1,2}([:.]\d\d)?(am|pm)|\d{1,2}[:.]\d\d", run[0]):
        return True  # "9.30", "9am"
    if len(run) >= 3 and run[0] in ("half", "quarter", *_NUMBERS) and run[1] in ("past", "to") and \
            (run[2] in _NUMBERS or run[2].isdigit()):
        return True
    return len(run) >= 2 and (run[0] in _NUMBERS or run[0].isdigit()) and run[1] in ("o'clock", "oclock")
