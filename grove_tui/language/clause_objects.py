"""Things listed as the object of a relative clause that says what is done at a place: "over to where
they sell tropical fish and rabbits" is one clause whose verb has two objects, so the room is read
from both ("fish and rabbits": the pet and aquatics zone, not the rabbit pens alone); the "and" starts
no new clause when only things (no person, no verb) follow it to the clause's end."""

from __future__ import annotations

from typing import TYPE_CHECKING

from grove_tui.language import lexicon as lx
from grove_tui.language.places import PlaceMatch

if TYPE_CHECKING:
    from grove_tui.language.place_described import Decided
    from grove_tui.language.people import People
    from grove_tui.language.sentence import Sentence

_THING_TAGS = frozenset({"NN", "NNS", "JJ", "DT", "PRP$", "CD", "HYPH"})


def joins_listed_things(s: Sentence, people: People, first: int, at: int) -> bool:
    """Whether the "and" at `at`, after the clause's verb and its object, joins another thing to that
    object: only words of a noun phrase (no person, no verb) follow it up to the end of the sentence,
    a punctuation mark or a word that starts a clause."""
    if s.low[at] != "and" or not any(s.is_verb(x) for x in range(first, at)) or s.w[at - 1].tag not in ("NN", "NNS"):
        return False
    k = at + 1
    while k < s.n and not s.is_punct(k) and s.low[k] not in lx.CLAUSE_STARTERS:
        if s.w[k].tag not in _THING_TAGS or s.is_verb(k) or people.is_person_noun(k) or s.low[k] == "robot":
            return False
        k += 1
    return k > at + 1 and s.w[k - 1].tag in ("NN", "NNS")


def lists_things(s: Sentence, people: People, first: int, end: int) -> bool:
    """Whether the clause from `first` to `end` lists two things or more as its verb's object."""
    return any(joins_listed_things(s, people, first, k) for k in range(first + 1, end))


def room_of_listed(s: Sentence, people: People, first: int, end: int, meant: Decided) -> Decided:
    """The room holding the things a clause lists ("where they sell tropical fish and rabbits"), when the
    reading of the whole clause took one fixture of that room: several things are kept in a room, not at
    one of its fixtures."""
    match = meant[0]
    room = s.index.entry(match.zone)
    if match.kind != "entity" or room is None or not lists_things(s, people, first, end):
        return meant
    return (PlaceMatch(room.name, room.kind, room.name, match.score, False), meant[1],
            f"{meant[2]}; things listed are kept in the room, {room.name}", meant[3])
