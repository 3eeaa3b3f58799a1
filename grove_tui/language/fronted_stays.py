"""A stay said before the sentence's people (round 24): "After forty minutes minding the cloakroom,
the pair of volunteers wander off to the café", "After ten minutes waiting in reception, a courier
walks to the kitchen". The length opens the sentence, after "after" and before a verb's "-ing" form:
the people stay that long where they are, then do what the sentence's verb says, whatever it is.
"""

from __future__ import annotations

from grove_tui.language.activity_stays import activity_stay_place
from grove_tui.language.alone_stays import past_manner
from grove_tui.language.counts import duration_at
from grove_tui.language.participle_stays import participle_spot
from grove_tui.language.sentence import Sentence
from grove_tui.language.stay_places import stay_place_after


def stay_first(s: Sentence, k: int) -> tuple[float, int] | None:
    """(seconds, index after the length) of "after <length> <doing>" at k, at a sentence's start or
    after a punctuation mark; else None."""
    if s.low[k] != "after" or (k > 0 and not s.is_punct(k - 1)):
        return None
    dur = duration_at(s, k + 1)
    if dur is None or dur[1] >= s.n:
        return None
    dur = (dur[0], past_manner(s, dur[1]))  # "After five minutes alone on the bench": the place follows
    if not (s.low[dur[1]].endswith("ing") or stay_place_after(s, dur[1]) or participle_spot(s, dur[1]) is not None):
        at = activity_stay_place(s, dur[1])  # "of silent study in the quiet room": the place's preposition
        return (dur[0], at) if at is not None else None  # "stuck at the desk" above
    return dur


def sentence_stay(s: Sentence, first: int) -> float | None:
    """The seconds of a stay that opens the sentence of the word at `first` ("After forty minutes
    minding the cloakroom, ..."); None when it opens with none."""
    k = first
    while k > 0 and s.w[k - 1].sentence == s.w[first].sentence:
        k -= 1
    said = stay_first(s, k)
    return said[0] if said is not None else None


def stayed_spots(s: Sentence) -> frozenset[int]:
    """The prepositions of the places fronted stays were spent at ("After forty minutes on the waiting
    chairs, a lad hobbles to ..."; round 46): where the walk starts is that place itself, a seat or a
    counter as much as a room, not the room around it."""
    spots: set[int] = set()
    for k in range(s.n):
        said = stay_first(s, k)
        if said is not None and said[1] < s.n and stay_place_after(s, said[1]) and s.low[said[1]] != "of":
            spots.add(said[1])
        elif said is not None and (spot := participle_spot(s, said[1])) is not None:
            spots.add(spot)  # "After twenty minutes hanging around the desk": that desk
    return frozenset(spots)
