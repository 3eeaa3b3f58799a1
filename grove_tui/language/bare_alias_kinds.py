"""A place matched only by a bare alias that is its head ("kiosk" of the phone kiosk), said with words
of another kind before the head: "the shoe repair kiosk", "the key-cutting kiosk" of a mall whose one
kiosk sells phones. The alias names the place when said alone; with a kind of its own before it, the
phrase names that kind, which must then agree with the place as any modifier must.

A room known by a bare word for its kind ("shop" of a station's newsagent, round 44) is held to more:
"the bike shop" is no newsagent, though "bike" comes 0.31 near it (any modifier passes at 0.3), so a
word before such a room's bare alias must be its own word, its fixtures' or its description's, a word
for the building, or clearly near the room's names: words of the room's own kind come at 0.53-0.70
("paper" 0.70, "news" 0.64, "convenience" 0.53 from the newsagent, "village" 0.53 from a farm shop),
those of other kinds of shop at 0.24-0.38 ("bike" 0.31, "book" 0.38, "gift" 0.32 from a farm shop).
"""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language.lexicon import PERSON_NOUNS
from grove_tui.language.places import PlaceIndex, PlaceMatch
from grove_tui.language.tokens import name_tokens

# How near a word before a room's bare alias must come to the room's names, or to the building.
KIND_NEAR = 0.4


def by_bare_alias(index: PlaceIndex, match: PlaceMatch, lemmas: Sequence[str]) -> bool:
    """Whether an exact match holds only by an alias that is the phrase's head alone, with other words
    before the head: none of the place's longer names is in the phrase."""
    entry = index.entry(match.name)
    if entry is None or entry.kind == "zone" or len(lemmas) < 2 or (lemmas[-1],) not in entry.phrases:
        return False
    said = set(lemmas)
    return not any(len(p) > 1 and set(p) <= said for p in entry.phrases)


def other_kind_of_room(index: PlaceIndex, match: PlaceMatch | None, lemmas: Sequence[str],
                       modifiers: Sequence[str]) -> bool:
    """Whether a room matched only by a bare alias that is the phrase's head ("shop") is said with a
    word before it that makes it another kind of room ("the bike shop" of a station whose shop is a
    newsagent; see the module doc)."""
    entry = index.entry(match.name) if match is not None else None
    if entry is None or entry.kind != "zone" or len(lemmas) < 2 or (lemmas[-1],) not in entry.phrases or \
            not modifiers:
        return False
    said = set(lemmas)
    if any(len(p) > 1 and set(p) <= said for p in entry.phrases):
        return False  # "the paper shop": a longer name of the room is in the phrase
    own = set(entry.tokens) | set(entry.tag_tokens) | set(name_tokens(entry.description))
    own |= {t for e in index.entries if e.zone == entry.name for t in e.tokens}
    for word in modifiers:
        if word in PERSON_NOUNS:
            continue  # "the men's toilet": whose it is, not another kind
        if word in own or any(len(word) > 3 and word in t for t in own) or index.near_building(word) >= KIND_NEAR:
            continue  # "paper" of a newsagent "selling newspapers"
        near = index.by_meaning(word, among={entry.name})
        if near and near[0].similarity < KIND_NEAR:
            return True
    return False
