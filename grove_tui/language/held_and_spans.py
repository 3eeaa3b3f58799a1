"""Two kinds of phrase after a place preposition that say no place, so nothing to refuse (round 46):

- a body part a thing is held in or on: "clipboard in hand", "a mug in each hand", "the baby in her arms",
  "a bag on his shoulder", "a folder under one arm": where a thing is carried, not a room the world lacks;
- a time said by an event or a break: "at the interval", "at half-time", "at the break", and "midway
  (halfway, partway) through the lecture / the concert / the match" (mid_events.py writes "mid-lecture"
  so), also when no comma ends the time before the subject ("Halfway through the matinee smoke drifts"). A named room is still a place: "at the break room", "through the lecture theatre" are headed by
  a room word, never by the event.
"""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.event_names import EVENT_WORDS
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import lemma

# Parts of the body a thing is held in, on or under.
_BODY = frozenset("hand hands arm arms fist fists palm palms lap shoulder shoulders hip hips back head "
                  "armpit grip grasp teeth mouth".split())
_HOLDING_PREPS = frozenset({"in", "on", "under", "over", "between"})
# Words that may stand before the body part ("in his hand", "in each hand", "under one arm", "in both hands").
_BEFORE_BODY = frozenset("his her their my your its our each one both either the a left right other free "
                         "spare own".split())
# A break or a span of an event said with "at" ("at the interval", "at half-time").
_AT_SPANS = frozenset("interval intermission half-time halftime break interlude changeover".split())
_PART_WAY = frozenset("midway halfway partway part-way half-way mid-way".split())


def held_or_span(s: Sentence, k: int, prep: str, at: int) -> bool:
    """Whether the phrase from k after the preposition at `at` is a body part or a span (module doc)."""
    head, end = _head(s, k)
    if head < 0:
        return False
    said = lemma(s.low[head])
    if prep in _HOLDING_PREPS and (said in _BODY or s.low[head] in _BODY):
        return all(s.low[x] in _BEFORE_BODY for x in range(k, head))
    if prep == "at" and (said in _AT_SPANS or s.low[head] in _AT_SPANS):
        return True  # "At the interval the alarms sound": a time, no place
    if prep == "through" and at >= 1 and s.low[at - 1] in _PART_WAY:
        # "Halfway through the matinee smoke drifts ...": with no comma the time runs into the subject,
        # so an event anywhere in the phrase ends the time
        return any(lemma(s.low[x]) in EVENT_WORDS or s.low[x] in EVENT_WORDS for x in range(k, head + 1))
    return False


def _head(s: Sentence, k: int) -> tuple[int, int]:
    """The last noun of the phrase from k (past determiners, adjectives, hyphened words) and its end."""
    j = k
    while j < s.n and (s.low[j] in lx.DETERMINERS or s.w[j].pos in ("DET", "PRON", "NUM")) and s.low[j] not in _BODY:
        j += 1
    head = -1
    while j < s.n and (s.w[j].pos in ("ADJ", "NOUN", "PROPN") or s.low[j] in _BODY or s.low[j] in _AT_SPANS):
        head = j
        j += 1
    return head, j
