"""A named kind of place the world lacks, round 33: "the key-cutting kiosk" where the world's only kiosk
is a phone kiosk or the customer service desk (called "kiosk"), "the shoe-repair booth" where the only
booth is a photo booth. The phrase contains a one-word alias of the place whole, so it matched exactly,
but only by its head: the words before it say what kind of kiosk it is, and when the world uses none
of them anywhere the place is one the world does not have, to refuse (and to read no place for it,
as for a kind of room the world lacks, `absent_kind`)."""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language import lexicon as lx
from grove_tui.language.place_meaning import MODIFIER_AGREES
from grove_tui.language.places import PlaceEntry, PlaceIndex, PlaceMatch
from grove_tui.language.user_kinds import USER_KINDS


# How near the whole phrase must be to the place for a kind the world never names to be that place:
# "first-class lounge" is 0.77 from the airline lounge, "key-cutting kiosk" 0.65 from a phone kiosk.
WHOLE_AGREES = 0.7


def by_head_alone(index: PlaceIndex, lemmas: Sequence[str], match: PlaceMatch | None) -> bool:
    """Whether an exact match came from the phrase's head alone, a one-word alias of the place, with
    words before it that are none of the place's own (nor a synonym or a tag of it) nor any other word
    of the world's, nor near it by meaning ("mobile" of the phone kiosk)."""
    if match is None or len(lemmas) < 2:
        return False
    entry = index.entry(match.name)
    if not match.exact:
        if entry is None or not _for_other_people(entry, lemmas):
            return False
        whole = index.by_meaning(" ".join(lemmas), among={entry.name})
        return not whole or whole[0].similarity < WHOLE_AGREES  # "the tourist centre" is the travel centre
    if entry is None or (lemmas[-1],) not in entry.phrases:
        return False
    if any(len(p) > 1 and all(t in lemmas for t in p) for p in entry.phrases):
        return False  # "the phone kiosk": a longer name of it said whole
    before = [t for t in lemmas[:-1] if t not in lx.PLACE_MODIFIERS and t not in lx.DETERMINERS]
    if not before or any(index.names_word(entry, t) or t in index.vocabulary for t in before):
        return False
    near = index.by_meaning(" ".join(before), among={entry.name})
    if near and near[0].similarity >= MODIFIER_AGREES:
        return False  # "the mobile kiosk" is the phone kiosk
    whole = index.by_meaning(" ".join(lemmas), among={entry.name})
    return not whole or whole[0].similarity < WHOLE_AGREES  # "the first-class lounge" is the airline lounge


def _for_other_people(entry: PlaceEntry, lemmas: Sequence[str]) -> bool:
    """Whether a phrase names its head for a kind of person ("the kids' section", "the teen zone") where the
    place that shares the head has it only for another kind ("reference section"), round 71: a section the
    world lacks, though "the children's toilets" are the toilets (called "toilets" alone)."""
    head = lemmas[-1]
    if (head,) in entry.phrases or not any(p and p[-1] == head for p in entry.phrases):
        return False
    before = [t for t in lemmas[:-1] if t not in lx.PLACE_MODIFIERS and t not in lx.DETERMINERS]
    return bool(before) and all(t in lx.PERSON_NOUNS and t not in USER_KINDS and t not in entry.tokens
                                and t not in entry.owners for t in before)
