"""Alarms that are no hazard (round 41).

An alarm is an evacuation cue ("the alarm goes off", "hear the alarm"), but not every alarm sends people
out. Three kinds of alarm call somebody to a job or are over, and leave the people's own verbs to say
what they do:
- an alarm that calls or is answered ("paged by a temperature alarm", "alerted by a pump alarm",
  "responding to a door alarm", "a nurse checks the alarm");
- an alarm on a thing that is watched, not a danger ("a humidity alarm sounds", "the freezer alarm
  goes off"), or a false one ("after a false alarm");
- an alarm that stops ("once the alarm clears", "when the alarm is silenced", "after the alarm stops").
A fire, smoke or evacuation alarm said as such still warns of a hazard unless it is answered or stops.
"""

from __future__ import annotations

from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import verb_lemma

_ALARMS = frozenset({"alarm", "alarms", "alert", "alerts"})
# Things watched by an alarm that is a job, not a danger ("a temperature alarm", "the fridge alarm").
_WATCHED = frozenset(
    "false temperature humidity pressure power ups battery door doors fridge freezer chiller pump drip monitor "
    "server disk rack cooling aircon hvac car bed call patient heart nurse oxygen ventilator level tank filter "
    "intruder security burglar clock phone pager test".split())
# Words of a hazard: an alarm said with one of them warns of a danger ("the fire alarm", "a smoke alarm").
_HAZARDOUS = frozenset("fire smoke gas evacuation emergency flood carbon co".split())
# Verbs by which an alarm calls somebody ("paged by", "alerted by", "called out by").
_CALLED = frozenset("page call alert summon wake prompt bleep buzz rouse trigger send".split())
# Verbs that answer an alarm ("responding to an alarm", "checks the alarm", "resets the alarm").
_ANSWERED = frozenset("respond answer check investigate reset silence acknowledge attend clear mute "
                      "cancel inspect deal see".split())
# Verbs by which an alarm stops ("the alarm clears", "the alarm is silenced", "the alarm stops").
_STOPPED = frozenset("clear stop end cease silence reset die cancel quiet mute finish fall go".split())
_QUIET = frozenset({"silent", "quiet", "off", "down", "over"})
# Words between a verb and an alarm ("responding to a door alarm", "checks on the server alarm").
_BETWEEN = frozenset("to on the a an that this its his her their same latest one".split())


def _verb_in(w: str, verbs: frozenset[str]) -> bool:
    """Whether the word is a form of one of the verbs ("paged", "responding", "silenced", "clears")."""
    return bool({w, verb_lemma(w), w[:-1], w[:-2], w[:-3], w[:-4]} & verbs)


def _start_of_phrase(s: Sentence, i: int) -> int:
    """The first word of the noun phrase the alarm at i ends ("a temperature alarm")."""
    k = i
    while k > 0 and not s.is_punct(k - 1) and (s.w[k - 1].pos in ("ADJ", "NOUN", "PROPN", "NUM")
                                               or s.low[k - 1] in _BETWEEN - {"to", "on"}):
        k -= 1
    return k


def _watched(s: Sentence, i: int) -> bool:
    """Whether the alarm at i is on a watched thing or false ("a humidity alarm", "a false alarm")."""
    mods = {s.low[k] for k in range(_start_of_phrase(s, i), i)}
    return bool(mods & _WATCHED) and not mods & _HAZARDOUS


def _answered(s: Sentence, i: int) -> bool:
    """Whether the alarm at i calls somebody or is answered ("paged by a ... alarm", "checks the alarm")."""
    k = _start_of_phrase(s, i) - 1
    while k >= 0 and s.low[k] in ("to", "on", "out", "up", "with"):
        k -= 1
    if k < 0:
        return False
    if s.low[k] == "by":
        j = k - 1
        while j >= 0 and s.low[j] in ("out", "up", "in"):
            j -= 1  # "called out by"
        return j >= 0 and _verb_in(s.low[j], _CALLED)
    return s.w[k].pos == "VERB" and _verb_in(s.low[k], _ANSWERED)


def _stopped(s: Sentence, i: int) -> bool:
    """Whether the alarm at i stops ("once the alarm on the video wall clears", "the alarm is silenced")."""
    for k in range(i + 1, min(i + 8, s.n)):
        if s.is_punct(k):
            return False
        if s.w[k].pos in ("VERB", "AUX") and s.low[k] not in ("is", "are", "was", "were", "has", "have", "been",
                                                              "gets", "got", "finally"):
            if _verb_in(s.low[k], frozenset({"fall", "go", "die", "went", "fell", "goes", "gone"})):
                return k + 1 < s.n and s.low[k + 1] in _QUIET - {"off"}
            return _verb_in(s.low[k], _STOPPED - {"fall", "go", "die"})
    return False


def calm_alarm(s: Sentence, i: int) -> bool:
    """Whether the word at i is an alarm that is no hazard (see the module doc), or the word by which
    such an alarm calls somebody ("alerted" in "alerted by a pump alarm")."""
    w = s.low[i]
    if w in _ALARMS:
        if w.startswith("alert") and s.w[i].pos != "NOUN":
            return False
        hazardous = bool({s.low[k] for k in range(_start_of_phrase(s, i), i)} & _HAZARDOUS)
        return _watched(s, i) or (not hazardous and _answered(s, i)) or _stopped(s, i)
    if _verb_in(w, _CALLED) and i + 1 < s.n and s.low[i + 1] in ("by", "out", "up"):
        for k in range(i + 1, min(i + 8, s.n)):
            if s.is_punct(k):
                return False
            if s.low[k] in _ALARMS:
                return calm_alarm(s, k)
    return False
