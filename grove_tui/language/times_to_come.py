"""A wait said by the time to come before people go (round 28): "6 lads in the cafe, heading to
platform 1 in 5 mins", "the family leave for gate A2 in ten minutes", "two nurses go to the canteen in
half an hour's time". "in" and a length after a verb of going is how long until they set off: they
wait that long where they are first. Not "within"/"in under" (how fast they get there) and not a
length that belongs to a place ("in the 5 minute zone")."""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language import lexicon as lx
from grove_tui.language.counts import duration_at
from grove_tui.language.sentence import Sentence

# Words after "in" that make the length a speed, not a time to come ("in under five minutes").
_SPEEDS = frozenset("under less over about".split())
# Verbs of going whose time to come is a wait before they go (beside the lexicon's verbs of walking).
_SETTING_OFF = frozenset("head leave go set move walk make depart board".split())


def time_to_come(s: Sentence, own: Sequence[int]) -> float | None:
    """The seconds of "in N minutes" said after a verb of going among a clause's words, or None."""
    going = False
    for k in own:
        if (s.is_verb(k) or s.w[k].pos == "NOUN" and not s.after_determiner(k)) and \
                (s.verb(k) in _SETTING_OFF or lx.INTENT_VERBS.get(s.verb(k)) == "walk"):  # "room head to": a noun at times
            going = True
            continue
        if not going or s.low[k] != "in" or k + 1 >= s.n or s.low[k + 1] in _SPEEDS:
            continue
        dur = duration_at(s, k + 1)
        if dur is None:
            continue
        end = dur[1]
        end += 1 if end < s.n and s.low[end] in ("'s", "’s", "'", "’") else 0
        end += 1 if end < s.n and s.low[end] == "time" else 0  # "in ten minutes' time"
        if end >= s.n or s.is_punct(end) and s.low[end] not in ("'", "’"):
            return dur[0]  # the clause ends with the time: "heading to platform 1 in 5 mins"
    return None
