"""A gathering named as the time of the rest (round 31): "When the youth club finishes, Bernadette
locks up and strolls into the main hall", "once the choir practice ends, ...", "after the toddler
group, ...". "Club", "choir", "group" also name groups of people, but as the subject of ending or
starting in a fronted time clause, or as the whole of an "after ..." phrase before a comma, they say
when the others act: nobody is there to simulate. The activities `activity_times.py` knows (tour,
class, meeting) are left to it; this reads the gatherings that are also clubs and groups."""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language.mention import Mention
from grove_tui.language.sentence import Sentence

_GATHERINGS = frozenset("club group choir practice playgroup assembly social disco quiz bingo mass service "
                        "session class meeting party lesson rehearsal match game show ceremony concert workshop "
                        "lecture seminar talk club-night night sale fair".split())
_TIME_WORDS = frozenset("once when after before until till whenever as".split())
_BARE_TIME_WORDS = frozenset({"after", "before", "until", "till"})  # "after the toddler group, ...": no verb
_DETERMINERS = frozenset("the this that our their his her its tonight's today's".split())
_ENDING = frozenset("end finish start begin close conclude stop wrap break resume run let kick".split())
_OVER = frozenset("over finished done ended through starting underway out".split())


def _event(s: Sentence, m: Mention) -> bool:
    """Whether the mention is only a gathering that ends or starts in a fronted time clause."""
    last = m.last
    if last + 1 < s.n and s.low[last + 1] in _GATHERINGS and s.low[last] not in _GATHERINGS:
        last += 1  # "after the kids club": the people word is the club's modifier
    if s.lemma(last) not in _GATHERINGS and s.low[last] not in _GATHERINGS:
        return False
    k = m.first - 1
    while k >= 0 and (s.low[k] in _DETERMINERS or s.low[k] in ("soon", "as")) and s.low[k] not in _TIME_WORDS:
        k -= 1
    if k < 0 or s.low[k] not in _TIME_WORDS or any(s.low[j] == "," for j in range(k, m.first)):
        return False
    after = last + 1
    if after >= s.n:
        return False
    if s.low[after] == "," or (s.low[after] in ("and", "then") and after + 1 < s.n):
        return s.low[k] in _BARE_TIME_WORDS and s.low[after] == ","  # "after the toddler group, ..."
    if s.low[after] in ("is", "has", "'s", "was", "gets", "are", "have", "were"):
        after += 1
        if after < s.n and s.low[after] in ("been", "got"):
            after += 1
        return after < s.n and (s.low[after] in _OVER or s.lemma(after) in _ENDING)
    return s.lemma(after) in _ENDING or s.low[after] in _ENDING


def without_named_events(s: Sentence, mentions: Sequence[Mention]) -> list[Mention]:
    """The mentions but the gatherings of a fronted time clause, when someone else is named."""
    dropped = [k for k, m in enumerate(mentions) if m.relation is None and _event(s, m)]
    if not dropped or len(dropped) == len(mentions) or any(m.relation is not None for m in mentions):
        return list(mentions)
    return [m for k, m in enumerate(mentions) if k not in dropped]
