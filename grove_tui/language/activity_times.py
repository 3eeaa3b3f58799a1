"""A time clause whose subject is an activity, not people (round 18): "Once the tour is over, ...",
"When the party ends, ...", "As soon as the class finishes, ...". "Tour", "party", "class" also name
groups of people, but as the subject of ending or starting after "once"/"when"/"after" they say when
the rest happens: nobody is there to simulate.
"""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language.mention import Mention
from grove_tui.language.sentence import Sentence

# Collectives that are also activities.
_ACTIVITIES = frozenset("tour party class lesson session meeting match game show service ceremony "
                        "concert performance seminar lecture workshop briefing rehearsal training shift".split())
_TIME_WORDS = frozenset("once when after before until till whenever as".split())
_DETERMINERS = frozenset("the this that our their his her its".split())
_ENDING = frozenset("end finish start begin close conclude stop wrap break resume run".split())
_OVER = frozenset("over finished done ended through starting underway".split())


def _time_subject(s: Sentence, m: Mention) -> bool:
    """Whether the mention is only an activity that ends or starts in a fronted time clause."""
    if s.lemma(m.last) not in _ACTIVITIES or m.first == 0:
        return False
    k = m.first - 1
    if k >= 0 and s.low[k] in _DETERMINERS:
        k -= 1  # the mention starts at its noun: "once the | tour"
    if k < 0 or s.low[k] not in _TIME_WORDS:
        return False
    after = m.last + 1
    if after < s.n and s.low[after] in ("is", "has", "'s", "was", "gets", "are"):
        after += 1
        return after < s.n and (s.low[after] in _OVER or s.lemma(after) in _ENDING)
    return after < s.n and s.lemma(after) in _ENDING


def without_activity_times(s: Sentence, mentions: Sequence[Mention]) -> list[Mention]:
    """The mentions but the activities of a fronted time clause, when someone else is named."""
    dropped = [k for k, m in enumerate(mentions) if m.relation is None and _time_subject(s, m)]
    if not dropped or len(dropped) == len(mentions) or any(m.relation is not None for m in mentions):
        return list(mentions)
    return [m for k, m in enumerate(mentions) if k not in dropped]
