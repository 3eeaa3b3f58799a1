"""A room named after a person said only by first name as the owner of someone else: "Edith's grandson
brings flowers from the front hall to her room", "Stan's daughter walks him back to his room". The
world names the room by that first name ("Edith's room"), and the possessive after it points back at
the name (the only one said): the room is that person's, not any room of the grandson's kind. Titled
names ("Mrs Okafor") and names in descriptions are read by language/named_owners.py and
language/described_owners.py; this is the bare name before "'s"."""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language.places import PlaceMatch
from grove_tui.language.sentence import Sentence

Decided = tuple[PlaceMatch, float, str, tuple[str, ...]]

_NOT_NAMES = frozenset({"the", "a", "an", "she", "he", "they", "her", "his", "their", "it", "we", "i", "you",
                        "then", "later", "meanwhile", "while", "when", "after", "before", "and", "but"})


def _possessor_name(s: Sentence, at: int) -> str | None:
    """The first name said with "'s" nearest before word `at` in its sentence ("edith"), or None."""
    for x in range(at - 2, -1, -1):
        if s.w[x].sentence != s.w[at].sentence:
            return None
        word = s.w[x].text
        if word[:1].isupper() and word.isalpha() and s.low[x] not in _NOT_NAMES and s.low[x + 1] in ("'s", "’s") \
                and s.w[x].pos in ("PROPN", "NOUN"):
            return s.low[x]
    return None


def owned_by_possessor_name(s: Sentence, at: int, k: int, lemmas: Sequence[str]) -> Decided | None:
    """The room "her/his <room>" at word k names when a first name said before it owns someone and the
    world names one room of that head by it ("Edith's room": room_1), else None."""
    if k >= s.n or s.low[k] not in ("her", "his") or not lemmas:
        return None
    name = _possessor_name(s, at)
    if name is None:
        return None
    head = lemmas[-1]
    rooms = [e for e in s.index.entries if e.kind == "zone" and head in e.tokens and
             any(phrase[:1] == (name,) for phrase in e.phrases)]
    if len(rooms) != 1:
        return None
    e = rooms[0]
    return (PlaceMatch(e.name, e.kind, e.zone, 1.0, True), 0.8,
            f"'{' '.join(lemmas)}' of {name}: {e.name}", ())
