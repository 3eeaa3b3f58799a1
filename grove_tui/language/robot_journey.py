"""The robot's way as its own journey, not a way people stand in (round 28): "the robot squeezes past
eighty freshers on its way to the lifts", "on the robot's way back", "as it makes its way to ward B".
"its way" after "on" or a verb of making or finding one's way is where the robot is going; nobody is
in its way by it."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import verb_lemma

# Words before "its way" that make it the robot's own journey.
_JOURNEY = frozenset("on make find wend pick thread weave push edge nose inch work".split())


def robots_own_way(s: Sentence, r: int) -> bool:
    """Whether the robot word (or "its") at r, with "way"/"route"/"path" after, is the robot's own
    journey: "on its way", "on the robot's way", "makes its way"."""
    before = r - 1
    while before > 0 and s.low[before] in lx.DETERMINERS:
        before -= 1
    return before >= 0 and (s.low[before] in _JOURNEY or verb_lemma(s.low[before]) in _JOURNEY)


def journey_words(s: Sentence) -> set[int]:
    """The words of "on its way to the lifts" said of the robot (named before): the robot's own way,
    none of the people's places, up to the clause's end."""
    found: set[int] = set()
    for k in range(s.n - 2):
        if s.low[k] != "on":
            continue
        r = k + 1 if s.low[k + 1] == "its" else k + 2 if s.low[k + 1] == "the" and s.low[k + 2] in lx.ROBOT_WORDS else None
        if r is None or not any(s.low[x] in lx.ROBOT_WORDS for x in range(k)):
            continue
        way = r + 1 + (r + 1 < s.n and s.low[r + 1] in ("'s", "’s"))
        if way >= s.n or s.low[way] not in ("way", "route", "journey"):
            continue
        end = way + 1
        while end < s.n and not s.is_punct(end) and s.low[end] not in ("and", "but", "while", "as", "when"):
            end += 1
        found |= set(range(k, end))
    return found
