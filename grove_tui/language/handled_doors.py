"""A person's own room said by its door as the thing a verb handles before they set off (round 47):
"Mrs Whitfield shuts her office door and crosses to the cash office", "the head teacher locks his
office door and heads to the hall", "the vicar pulls her vestry door to and walks up the aisle".
"Her office door" is a thing of her office: she was in that office, so it is where she starts, not one
of its doors (which may be any of them: the words "office door" fit the back door as well, or the door of another room of that kind: "the kids
slam their bedroom door" where "bedroom door" names the parents' one). Only a
door named with a possessive and handled by a verb of shutting, locking or opening is so read; "leaves
by her office door" goes through the door.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

from grove_tui.language import lexicon as lx
from grove_tui.language.place_meaning import Decided
from grove_tui.language.places import PlaceMatch
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import verb_lemma

_HANDLING = frozenset("shut close lock unlock open slam bang bolt latch pull push prop secure".split())


def handled_door_room(s: Sentence, prep: str, at: int, lemmas: Sequence[str], match: PlaceMatch | None,
                      owned: Callable[[Sequence[str]], Decided | None]) -> Decided | None:
    """The owner's room whose door a verb at or just before `at` handles ("shuts her office door"),
    read through `owned` (the owner's room the words name) on the words before the door word; None
    when the phrase is not so said."""
    if match is None or match.kind != "door" or len(lemmas) < 2 or lemmas[-1] not in lx.DOOR_WORDS:
        return None
    if not prep.startswith("obj:"):
        return None
    if not any(_handles(s, x) for x in range(max(0, at - 1), min(s.n, at + 1))):
        return None
    room = owned(lemmas[:-1])
    if room is None or room[0].kind != "zone":
        return None
    if not _door_of(s, room[0].name, match.name) and not _door_of_same_kind(s, match.name, lemmas[-2]):
        return None
    return room


def _handles(s: Sentence, x: int) -> bool:
    """Whether word x is a verb of shutting, locking or opening ("shuts", "locked", "pulls")."""
    word = s.low[x]
    return s.lemma(x) in _HANDLING or verb_lemma(word) in _HANDLING or word.removesuffix("s") in _HANDLING or \
        word.removesuffix("ed") in _HANDLING or word.removesuffix("d") in _HANDLING


def _door_of_same_kind(s: Sentence, door: str, head: str) -> bool:
    """Whether the door the words matched belongs to (or leads into) another room that the room word
    names as well ("her office door" matched the school office's door, the head's office is hers):
    the owner, not the door's name, says which of those rooms it is."""
    rooms = {z.name for z in s.index.world.zones for d in z.doors if d.name == door} | \
        {d.leads_to for z in s.index.world.zones for d in z.doors if d.name == door and d.leads_to}
    return any(e.kind == "zone" and e.name in rooms and head in e.tokens for e in s.index.entries)


def _door_of(s: Sentence, zone: str, door: str) -> bool:
    """Whether the door is one of the room's own or leads into it."""
    return any(d.name == door and (z.name == zone or d.leads_to == zone) for z in s.index.world.zones for d in z.doors)
