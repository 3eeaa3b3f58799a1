"""What people wear or carry said as a bare plural after "in", when the world has a fixture of that name
(round 44): "three Cub Scouts in grip socks set off from the locker room" (a grip sock machine),
"two recruits in BA sets jog from the kit room" (the BA sets on their rack), "skaters in hire skates".
The clothes pass (worn_clothes.py) keeps any phrase a world's name shares, so the fixture was taken
for where the people are, and it outranked the room they set off from. A person is never "in" a
fixture said with no determiner and in the plural whose head is a thing worn or held (socks, suits,
sets of kit, aids): that is what they have on; a room of the world ("patients in ward B", "kids in
ball pits" of a world whose pits are rooms) and furniture ("actors in costume rails") are still places."""

from __future__ import annotations

from collections.abc import Callable

from grove_tui.language.places import PlaceMatch
from grove_tui.language.sentence import Sentence


def worn_fixture(s: Sentence, k: int, at: int, end: int, match: PlaceMatch | None,
                 is_person: Callable[[int], bool]) -> bool:
    """Whether the phrase k..end after the "in" at `at`, right after a word for people (or a plural
    noun no place names: "Cub Scouts"), is a bare plural that names only a fixture of the world, or
    nothing: worn or carried, no place."""
    if at < 1 or at >= s.n or s.low[at] != "in" or k != at + 1 or end <= k or s.w[end - 1].tag != "NNS":
        return False
    if not (is_person(at - 1) or s.w[at - 1].tag in ("NNS", "NNPS") and not s.index.knows(s.lemma(at - 1))):
        return False
    if s.w[k].pos in ("DET", "NUM", "PRON") or any(s.low[x] in ("'s", "’s") for x in range(k, end)):
        return False
    return (match is None or match.kind != "zone") and s.lemma(end - 1) in WORN_HEADS


# Heads of what people wear or carry on them, in the plural ("grip socks", "BA sets", "bunny suits").
WORN_HEADS = frozenset("sock stocking tights suit set kit gear harness helmet lid goggle glove boot shoe trainer skate hat cap "
                       "aid armband float overall gown apron mask vest jacket coat lanyard badge tag band "
                       "wristband headphone earmuff glass sunglasses scrub uniform tabard".split())
