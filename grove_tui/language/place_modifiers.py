"""Words a world uses only to say whose a place is, and adjectives only people take.

"the jury room", "the juror room", "the witness suite", "the harbour master office": the world
knows "juror", "witness" and "master", but only before another word of a place's name, never as
a name's last word. Such a word on its own ("five jurors walk", "a witness leaves") names who
the place is for, not the place, so the reader may take it for people when the sentence says they
do what people do. "a nervous witness", "its worried owner", "a handcuffed defendant": an
adjective of mind, mood or body that only people take makes the noun a person's."""

from __future__ import annotations

from functools import lru_cache
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from grove_tui.language.places import PlaceIndex

# Adjectives said of people and not of things: moods, states of mind or body, restraint.
PERSON_ADJECTIVES = frozenset("""nervous worried anxious tired weary exhausted sleepy elderly hungry thirsty
angry furious impatient excited bored confused frightened scared terrified upset distressed distraught
grumpy cheerful happy sad annoyed frustrated irate agitated panicked panicking pregnant frail disabled
blind deaf limping injured wounded bleeding handcuffed shackled restrained drunk tipsy sober jetlagged
homesick lonely shy curious eager keen bewildered flustered harassed harried stressed relieved grieving
tearful sobbing crying smiling laughing giggling yawning chatty talkative sullen elated jubilant
disgruntled hopeful apprehensive""".split())

_NUMBERED = ("1", "2", "3", "4", "5", "6", "7", "8", "9", "a", "b", "c", "d", "one", "two", "three", "four")


@lru_cache(maxsize=32)
def _place_heads(index: PlaceIndex) -> frozenset[str]:
    """The words that end some name of a place (a number or letter after a name does not end it:
    "court 1", "gate b"), its type's last word, and its tags."""
    heads: set[str] = set()
    for e in index.entries:
        heads |= e.tag_tokens
        for p in e.phrases:
            words = [t for t in p if t.isalpha() and t not in _NUMBERED]
            if words:
                heads.add(words[-1])
        for t in e.types:
            if t.split():
                heads.add(t.split()[-1])
    return frozenset(heads)


def only_modifies_places(index: PlaceIndex, lem: str) -> bool:
    """Whether the world uses the word only before another word of a place's name ("juror" in "juror
    room"), never as the last word of a name, a type or a tag."""
    return lem in index.vocabulary and lem not in _place_heads(index)


def names_a_place(index: PlaceIndex, lem: str) -> bool:
    """Whether a word names a place of the world on its own: a word it knows, not only as the first
    word of a name that says whose the place is."""
    return index.knows(lem) and not only_modifies_places(index, lem)
