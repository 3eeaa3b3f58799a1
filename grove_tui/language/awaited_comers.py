"""People awaited in a time clause (round 69): "two porters hover by the lifts until the night team turns
up", "a visitor waits in reception till the consultant comes down", "Just before the headliner comes on,
sixty fans drift ...", "a porter loiters in the corridor before the doctors arrive". Those who are still
to come set when the scene ends or starts; they are not in it, so they are no group of the scene, when
someone else is named. (A fronted "Before the boss gets in, ..." is taken out before parsing,
awaited_arrivals.py; a vehicle or a call waited for, awaited_events.py.)"""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language.mention import Mention
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import verb_lemma

_TIME_WORDS = frozenset({"until", "till", "til", "'til", "untill", "before"})
# Verbs of arriving said alone ("until the surgeon arrives", "before the doctors come").
_ARRIVE = frozenset("arrive come return appear reappear emerge".split())
# Verbs of arriving said with a particle ("turns up", "shows up", "gets in", "comes on", "rolls in").
_ARRIVE_WITH = frozenset("come turn show get roll wake clock pop swing drop rock".split())
_PARTICLES = frozenset("up in on down back round over along through out by here there onstage".split())
_AUX = frozenset("has have had is are was were finally eventually actually at last".split())
_STEPS = 6  # words from the time word to the awaited people's first word


def _awaited(s: Sentence, m: Mention) -> bool:
    """Whether m is the subject of an "until"/"before" clause of arriving (module doc)."""
    before = next((k for k in range(m.first - 1, max(-1, m.first - 1 - _STEPS), -1)
                   if s.is_punct(k) or s.low[k] in _TIME_WORDS), None)
    if before is None or s.is_punct(before) or s.w[before].pos == "VERB":
        return False
    if any(s.w[k].pos in ("VERB", "AUX", "ADP") for k in range(before + 1, m.first)):
        return False  # "before leaving with the nurses", "until after the doctors come"
    j = m.last + 1
    while j < s.n and s.low[j] in _AUX:
        j += 1
    if j >= s.n:
        return False
    verb = verb_lemma(s.low[j])
    if verb in _ARRIVE:
        return True
    if verb in ("walk", "stroll", "breeze") and j + 1 < s.n:
        return s.low[j + 1] == "in"  # "until the boss walks in" (not "before the kids walk over to ...")
    return verb in _ARRIVE_WITH and j + 1 < s.n and s.low[j + 1] in _PARTICLES


def without_awaited_comers(s: Sentence, mentions: Sequence[Mention]) -> list[Mention]:
    """The mentions but the people an "until"/"before" clause waits to arrive, when someone else is named."""
    dropped = {k for k, m in enumerate(mentions) if m.relation is None and _awaited(s, m)}
    if not dropped or len(dropped) == len(mentions):
        return list(mentions)
    return [m for k, m in enumerate(mentions) if k not in dropped]
