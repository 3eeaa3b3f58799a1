"""A hazard's source said to be outside the building (round 44): "smoke blows in from a bonfire next
door", "fumes drift over from the chip shop across the road", "smoke from a barn fire down the lane".
Nobody in the scene goes there or comes from there, so its noun is no place to refuse, whatever its
head ("the restaurant next door" is no room of this building either); language/hazards.py asks."""

from __future__ import annotations

from grove_tui.language.sentence import Sentence

# Words that say where outside the building a thing is, after its noun phrase.
_OUTSIDE = (("next", "door"), ("across", "the", "road"), ("across", "the", "street"), ("over", "the", "road"),
            ("over", "the", "way"), ("down", "the", "road"), ("down", "the", "street"), ("down", "the", "lane"),
            ("up", "the", "road"), ("up", "the", "street"), ("nearby",), ("outside",), ("in", "the", "street"),
            ("on", "the", "estate"), ("across", "the", "way"))


def outside_at(s: Sentence, k: int) -> int:
    """The number of words of such a phrase at k ("next door": 2), or 0."""
    for said in _OUTSIDE:
        if tuple(s.low[k:k + len(said)]) == said:
            return len(said)
    return 0
