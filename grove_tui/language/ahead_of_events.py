"""An event people are early for, said with "ahead of" or "in advance of": "queuing at the dome doors
ahead of the 3 pm star show", "gather in the foyer in advance of the lecture". Like "for the show", the
event is why they are there (their purpose), not a place: the phrase runs to its head noun, which must
name an event (a show, a match, a service, a lecture) and not a vehicle or a person ("ahead of the
coach", "ahead of their teacher" say who goes first).

An event said with a day's possessive ("ahead of tonight's whist drive", "in advance of Saturday's fun run")
is an event whatever its head: a day has occasions, not places or people. A workplace's short meetings
("the nine o'clock huddle", "the morning stand-up", issue 29) are events here too."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.event_names import EVENT_WORDS
from grove_tui.language.sentence import Sentence

# Less the words that also name people ("ahead of the class", "ahead of the tour party": who goes first);
# with a workplace's short meetings, which only "ahead of" a time makes events ("ahead of the 9 am huddle").
_MEETINGS = frozenset("huddle standup stand-up catch-up catchup debrief sync retro retrospective handover "
                      "hand-over review demo check-in all-hands inspection appointment interview".split())
_EVENTS = (EVENT_WORDS | _MEETINGS) - lx.PERSON_NOUNS
# Days whose possessive opens an event ("tonight's", "Saturday's").
_DAYS = frozenset("""tonight tomorrow today yesterday evening morning afternoon weekend week month year monday
tuesday wednesday thursday friday saturday sunday""".split())


def ahead_of_event(s: Sentence, i: int) -> int | None:
    """The end (exclusive) of an event phrase opened at word i by "ahead of" / "in advance of", else None."""
    if s.low[i] == "ahead" and i + 1 < s.n and s.low[i + 1] == "of":
        start = i + 2
    elif s.low[i] == "in" and tuple(s.low[i + 1:i + 3]) == ("advance", "of"):
        start = i + 3
    else:
        return None
    if start + 2 < s.n and s.low[start] in _DAYS and s.low[start + 1] in ("'s", "’s"):
        end = start + 2
        while end < s.n and end < start + 6 and s.w[end].pos in ("NOUN", "PROPN", "ADJ", "VERB") and \
                s.low[end] not in lx.CLAUSE_STARTERS and s.low[end] not in lx.PLACE_PREPOSITIONS:
            end += 1
        return end if end > start + 2 else None  # "ahead of tonight's whist drive"
    end = s.phrase_end(start)
    if end <= start or end > s.n:
        return None
    head = end - 1
    joined = "".join(s.low[max(start, head - 2):end])  # "stand-up", "check-in" split at the hyphen
    return end if s.lemma(head) in _EVENTS or s.low[head] in _EVENTS or joined in _MEETINGS else None
