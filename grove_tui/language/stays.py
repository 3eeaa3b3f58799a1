"""How long people stay, in the ways people say it beyond a number and a unit (round 13c).

`counts.duration_at` reads "five minutes", "half an hour", "a quarter of an hour". Said with "for",
a stay is also a vague spell ("for a bit", "for a while", "for ages"), a unit and a half ("an hour and
a half"), or the whole scenario ("for the rest of the run", "for the whole shift"). Said without
"for", it is the whole scenario ("until closing", "till the end", "the whole time", "throughout") or a
part of the day ("all afternoon"). A stay for the whole scenario has no number of seconds: they stay
until the run ends, which is what a wait with no length already means, but its words are a stay,
never a purpose ("for the rest of the run") nor a pace ("run").
"""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language import lexicon as lx
from grove_tui.language.counts import duration_at
from grove_tui.language.fronted_stays import stay_first
from grove_tui.language.sentence import Sentence
from grove_tui.language.times_to_come import time_to_come
from grove_tui.language.tokens import lemma

# Vague spells after "for", in seconds: a typical length of each.
_SPELLS: dict[tuple[str, ...], float] = {
    ("a", "bit"): 120.0, ("a", "little", "bit"): 120.0, ("a", "little", "while"): 300.0, ("a", "while"): 600.0,
    ("a", "short", "while"): 300.0, ("a", "long", "while"): 1800.0, ("a", "good", "while"): 1200.0,
    ("ages",): 1800.0, ("a", "long", "time"): 1800.0, ("a", "short", "time"): 300.0, ("a", "spell"): 600.0,
}
# Words naming the scenario or a stretch of it that lasts as long ("the rest of the run", "the whole shift").
_WHOLE_NOUNS = frozenset("run scenario simulation session shift time duration episode night".split())
_WHOLE_WORDS = frozenset({"whole", "entire", "full"})
# "until closing", "till the end", "until close": the scenario's end.
_UNTIL = frozenset({"until", "till", "til", "untill"})
# "make a coffee last half an hour": making a thing last as long as one stays.
_MAKING = frozenset({"make", "makes", "made", "making"})
# "kill 45 mins in the green room", "spend an hour in the café": passing that long there.
_SPENDING = frozenset("kill kills killed killing spend spends spent spending pass passes passed passing".split())
# Words after a length that end the stay it says ("like 10 min before going in", "like 10 min, then").
_THEN = frozenset({"before", "then", "and", "b4"})
_ENDS = frozenset({"closing", "close", "end", "finish", "closing-time", "home-time", "lights-out"})


def whole_stay(s: Sentence, k: int) -> int | None:
    """The end of a phrase at k that says the whole scenario ("the rest of the run", "the whole time",
    "the entire shift"); None when there is none."""
    low = s.low
    if k + 3 < s.n and low[k] == "the" and low[k + 1] == "rest" and low[k + 2] == "of":
        j = k + 3 + (low[k + 3] == "the")
        if j < s.n and low[j] in _WHOLE_NOUNS:
            return j + 1
    j = k + (low[k] in ("the", "a") if k < s.n else 0)
    if j + 1 < s.n and low[j] in _WHOLE_WORDS and low[j + 1] in _WHOLE_NOUNS:
        return j + 2
    return None


def stay_after_for(s: Sentence, k: int) -> tuple[float | None, int] | None:
    """(seconds, or None for the whole scenario; index after) of a stay said after "for" at k - 1."""
    whole = whole_stay(s, k)
    if whole is not None:
        return None, whole
    for words, seconds in _SPELLS.items():
        if tuple(s.low[k:k + len(words)]) == words:
            return seconds, k + len(words)
    dur = duration_at(s, k)
    if dur is None:
        return None
    seconds, end = dur
    if tuple(s.low[end:end + 3]) == ("and", "a", "half") and lemma(s.low[end - 1]) in lx.DURATION_UNITS:
        return seconds * 1.5, end + 3  # "an hour and a half"
    return seconds, end


def stay_said_alone(s: Sentence, k: int) -> tuple[float | None, int] | None:
    """A stay with no "for" at k: the whole scenario ("until closing", "till the end of the run", "the
    whole time", "throughout") or a part of the day ("all afternoon")."""
    low = s.low
    if low[k] in _UNTIL and k + 1 < s.n:
        j = k + 1 + (low[k + 1] == "the")
        if j < s.n and low[j] in _ENDS:
            j += 1
            if j < s.n and low[j] == "time":
                j += 1  # "until closing time"
            if j + 1 < s.n and low[j] == "of" and (low[j + 1] in _WHOLE_NOUNS or low[j + 1] == "the"):
                j += 2 + (low[j + 1] == "the")  # "till the end of the run"
            return None, j
        return None
    if low[k] in ("last", "lasts") and any(low[x] in _MAKING for x in range(max(0, k - 5), k)):
        dur = duration_at(s, k + 1)  # "makes one cuppa last 40 minutes": a stay that long
        return (dur[0], dur[1]) if dur is not None else None
    if low[k] in _SPENDING and k > 0 and (dur := duration_at(s, k + 1)) is not None:
        return dur  # "kill 45 mins in dressing room 3", "spend an hour in the café"
    if low[k] in ("about", "around", "like") and k > 0 and not s.is_punct(k - 1) and (dur := duration_at(s, k + 1)) is not None \
            and (dur[1] >= s.n or s.is_punct(dur[1]) or low[dur[1]] in _THEN):
        return dur  # "waitin @ departures board like 20 min" (written "about"): a stay that long
    if (first := stay_first(s, k)) is not None:
        return first  # "After forty minutes minding the cloakroom, ...": a stay before the rest
    if low[k] == "throughout" and (k + 1 >= s.n or s.is_punct(k + 1)):
        return None, k + 1
    if tuple(low[k:k + 3]) == ("all", "the", "time"):
        return None, k + 3
    if low[k] == "all" and k + 1 < s.n and low[k + 1] in lx.DAY_PERIODS:
        return lx.DAY_PERIODS[low[k + 1]], k + 2  # "waits outside the cinema all afternoon"
    if low[k] in ("the", "all") and (low[k] == "the" or k + 1 < s.n and low[k + 1] == "the"):
        j = k + (low[k] == "all")
        whole = whole_stay(s, j)
        if whole is not None and (k == 0 or low[k - 1] not in ("for", "of", "during")):
            return None, whole  # "reads in the reading room the whole time", "all the time"
    return None


def stay_in(s: Sentence, own: Sequence[int]) -> float | None:
    """The seconds of the first stay said with no "for" among a clause's words (None for none, or for
    one that lasts the whole scenario). Read over all of them: a place phrase may have run on over it
    ("outside the cinema all afternoon")."""
    for k in own:
        said = stay_said_alone(s, k)
        if said is not None:
            return said[0]
    return time_to_come(s, own)  # "heading to platform 1 in 5 mins": they wait that long first
