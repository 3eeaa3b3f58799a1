"""A fronted stay said with a participle before its place (round 47): "After twenty minutes hanging
around the check-in desk, a traveller ...", "After ten minutes sitting at the bar, ...", "After half an
hour queuing by the counter, ...". The place after the "-ing" word (and a particle such as "around" or
"about") is where the stay was spent, so it is where they start: that thing itself, not its room, as
`stay_places` already reads "After forty minutes on the waiting chairs". A thing handled all that while
("After half an hour fiddling with the bollards") is where they were too (round 54). A past participle
of being kept somewhere ("After twenty minutes stuck at the help desk", "stranded by the gate"; issue 29)
says where the stay was spent as the "-ing" word does.
"""

from __future__ import annotations

from grove_tui.language.sentence import Sentence
from grove_tui.language.stay_places import stay_place_after

# Particles that may stand between the "-ing" word and the place ("hanging around", "hanging about near").
_PARTICLES = frozenset({"around", "round", "about"})
# Past participles of being kept or settled somewhere, said where an "-ing" word would be.
STAY_PARTICIPLES = frozenset("stuck stranded marooned trapped sat stood parked camped wedged seated perched "
                             "slumped huddled holed".split())


def participle_spot(s: Sentence, k: int) -> int | None:
    """The index of the preposition that says where a stay said with an "-ing" word at k was spent
    ("hanging around the desk": "around"; "sitting at the bar": "at"); None when none follows."""
    if k >= s.n or not (s.low[k].endswith("ing") and len(s.low[k]) >= 5 or s.low[k] in STAY_PARTICIPLES):
        return None
    j = k + 1
    with_at = j + 1 if j < s.n and s.low[j] in _PARTICLES else j
    if with_at < s.n and s.low[with_at] == "with" and _place_follows(s, with_at):
        return with_at  # "fiddling with the hook-up posts", "messing about with the scanner": the thing handled
    if j < s.n and s.low[j] in _PARTICLES:
        if j + 1 < s.n and stay_place_after(s, j + 1):
            return j + 1  # "hanging about near the gate"
        return j if _place_follows(s, j) else None
    if j < s.n and s.low[j] == "from" and _place_follows(s, j):
        return j  # "watching from the viewing window": where they watched from, that spot itself
    return j if j < s.n and stay_place_after(s, j) else None


def _place_follows(s: Sentence, j: int) -> bool:
    """Whether "around"/"about"/"with" at j is followed by a place of the world up to the clause's comma."""
    end = j + 1
    while end < s.n and (not s.is_punct(end) or s.hyphen_inside(end)):  # "the hook-up posts"
        end += 1
    return end < s.n and s.low[end] == "," and any(s.index.knows(s.lemma(x)) or s.index.knows(s.low[x])
                                                  for x in range(j + 1, end))
