"""Rooms that carry the name of whoever they belong to. A care home names its residents' rooms
("Mrs Okafor's room"), a school its classes' rooms ("year 1 classroom"): "a carer wheels Mrs Okafor
from her room" starts in Mrs Okafor's room, not the carer's own, and "Year 1 ... troop from their
classroom" in year 1's, not any classroom. The owner is the nearest titled name (or school class)
said before the possessive in its sentence, the pronoun agreeing ("her" is no Mr's). The world's
own person names are names though places' words too (role_words.world_person_name)."""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language import lexicon as lx
from grove_tui.language.described_owners import owned_by_described_name, owned_by_name_said, said_owner_name
from grove_tui.language.elided_owners import elided_owned
from grove_tui.language.named_things import things_of_name
from grove_tui.language.place_owner import owner_at
from grove_tui.language.places import PlaceMatch
from grove_tui.language.possessor_rooms import owned_by_possessor_name
from grove_tui.language.sentence import Sentence

__all__ = ["elided_owned", "owned_by_name", "owner_at", "said_owner_name"]

Decided = tuple[PlaceMatch, float, str, tuple[str, ...]]

_HIS = frozenset({"mr", "sir", "father", "uncle"})
_HER = frozenset({"mrs", "ms", "miss", "dame", "sister", "auntie"})
_CLASS_WORDS = frozenset({"year", "class", "form", "grade"})


def _owner_words(s: Sentence, at: int, pronoun: str) -> tuple[tuple[str, ...], ...] | None:
    """The ways of saying the nearest owner named before word `at` in its sentence: (("mrs",
    "okafor"),) or (("year", "1"),)."""
    for x in range(at - 1, -1, -1):
        if s.w[x].sentence != s.w[at].sentence:
            return None
        title = s.low[x].rstrip(".")
        if title in lx.TITLES and x + 1 < at and s.w[x + 1].text[:1].isupper():
            if (pronoun == "her" and title in _HIS) or (pronoun == "his" and title in _HER):
                continue
            # As said and as the index keeps it, by lemmas ("Dr Hughes": "dr hughe")
            return ((title, s.low[x + 1]), (title, s.lemma(x + 1))) if pronoun != "their" else None
        if s.low[x] in _CLASS_WORDS and x + 1 < at and s.low[x + 1][:1].isdigit() and pronoun == "their":
            return ((s.low[x], s.low[x + 1]),)
    return None


def owned_by_name(s: Sentence, at: int, k: int, lemmas: Sequence[str]) -> Decided | None:
    """The room a possessive at word k names when its owner's name is one of the world's ("her
    room" of Mrs Okafor: room_3), else None."""
    if k < s.n and s.low[k] not in ("her", "his", "their") and lemmas:
        return owned_by_name_said(s, k, lemmas)  # "to Priya Shah's office": by the world's description
    if k >= s.n or s.low[k] not in ("her", "his", "their") or not lemmas:
        return None
    owner = _owner_words(s, at, s.low[k])
    if owner is None:
        return owned_by_described_name(s, at, k, lemmas) or owned_by_possessor_name(s, at, k, lemmas)
    head = lemmas[-1]
    n = len(owner[0])
    rooms = [e for e in s.index.entries if e.kind == "zone" and head in e.tokens and any(
        phrase[x:x + n] in owner for phrase in e.phrases for x in range(len(phrase) - n + 1))]
    rooms = rooms or things_of_name(s.index, owner, head)  # "his own bed": the bed of his room
    if len(rooms) != 1:
        return owned_by_described_name(s, at, k, lemmas)
    e = rooms[0]
    return (PlaceMatch(e.name, e.kind, e.zone, 1.0, True), 0.85,
            f"'{' '.join(lemmas)}' of {' '.join(owner[0])}: {e.name}", ())
