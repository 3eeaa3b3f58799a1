"""Kinds of place a world may lack: a phrase whose words name one ("the planetarium", "the planetarium
dome", "the sauna room", "the bowling alley") names that kind of place; in a world with no zone, fixture
or alias of that kind (nor a synonym, nor a name as near as a synonym) it is refused as a place the
world lacks, never matched by meaning to a loosely similar room (a museum's workshop room is no
planetarium). Read for language/place_phrases.py."""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language import lexicon as lx
from grove_tui.language.places import PlaceIndex
from grove_tui.language.sentence import Sentence
from grove_tui.language.place_kind_words import BUILDING_KINDS as BUILDING_KINDS, PLACE_KINDS as PLACE_KINDS
from grove_tui.language.sport_kinds import only_the_head
from grove_tui.language.tier_places import absent_tier, tier_place as tier_place
from grove_tui.language.tokens import lemma

# A name this near the kind's word in meaning is that kind under another word ("creche": "nursery").
SYNONYM_NEAR = 0.75
# A building kind this near what the world is, is the world itself ("the school" of a dance school).
WORLD_NEAR = 0.6


def absent_kind(index: PlaceIndex, lemmas: Sequence[str]) -> str | None:
    """The kind of place a phrase names that the world has none of ("planetarium" of "the planetarium
    dome"), or None."""
    if (tier := absent_tier(index, lemmas)) is not None:
        return tier  # "the upper circle" of a theatre with none
    words = [t for t in lemmas if t]
    pairs = ["_".join(words[i:i + 2]) for i in range(len(words) - 1)]
    for kind in [*pairs, *words]:
        building = kind in BUILDING_KINDS
        if kind not in PLACE_KINDS and not building:
            continue
        parts = kind.split("_")
        if building and kind not in PLACE_KINDS and words[-len(parts):] != parts:
            continue  # "the college bar", "the museum shop": a building said of the place, not named as it
        if all(_named(index, p) for p in parts) or any(_named(index, p) for p in parts if p not in _SHARED):
            return None  # the world has it ("bowling alley" where an alley is a bowling alley), or a synonym
        said = kind.replace("_", " ")
        if building and index.near_building(said) >= WORLD_NEAR:
            return None  # "the supermarket" of a supermarket: the building itself
        near = index.by_meaning(said)
        if near and near[0].similarity >= SYNONYM_NEAR and not only_the_head(kind, near[0].nearest):
            return None
        return said
    return None


def _named(index: PlaceIndex, word: str) -> bool:
    """Whether some place is called by this word or a synonym of it: a tag is what a place is for, not
    what it is (a piano tagged "music" is no music room)."""
    return index.knows(word) and (any(word in e.tokens for e in index.entries) or word not in index.vocabulary)


# Words of a kind's name that other places share ("play" of "play area", "room" of "prayer room").
_SHARED = frozenset("baby changing change first property parent room area play hot tub ward post office bar beauty steam labour skate park alley studio hall "
                    "screening".split())


def kind_continues(phrase: Sequence[str], word: str) -> bool:
    """Whether `word` goes on a kind of place the phrase began ("baby" then "changing"), though a
    parser reads it as a verb."""
    return bool(phrase) and f"{phrase[-1]}_{word}" in PLACE_KINDS


def gerund_before_room(s: Sentence, j: int) -> bool:
    """Whether the "-ing" word at j says what a room right after it is for ("the old changing rooms", "the
    drying room"), not a verb after a place phrase ("in the cafeteria evacuating"), round 44."""
    return s.low[j].endswith("ing") and j + 1 < s.n and s.w[j + 1].pos == "NOUN" and \
        lemma(s.low[j + 1]) in lx.GENERIC_PLACE_HEADS | _ROOM_HEADS


_ROOM_HEADS = frozenset("hall lounge office bay booth suite village block shed cubicle pen".split())


def gerund_kind(s: Sentence, lemmas: Sequence[str], end: int) -> bool:
    """Whether an "-ing" word before a place phrase's head says what kind of place it is: before a head
    that names something ("the vending machines"), or right before a word for any room ("the changing
    rooms", round 44: else "rooms" alone matched the staff room)."""
    if not lemmas:
        return False
    return lemmas[-1] not in lx.GENERIC_PLACE_HEADS or (end >= 2 and s.w[end - 2].tag == "VBG" and
                                                        s.low[end - 2].endswith("ing"))
