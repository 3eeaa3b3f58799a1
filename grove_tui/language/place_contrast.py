"""Two places said against each other, for language/clauses.py:

- one used and one not, that the world keeps in one room: "take the stairs, not the lifts" in a hospital
  whose lift lobby answers to "stairs" and "lifts" alike. Read as the room, the contrast says nothing
  (the group would use and avoid the same place); the room's fixtures tell them apart (its stairwell and
  its two elevators), so each phrase is read as the fixtures of that room its head names;
- one left for the other: "leaves the auditorium for the planetarium" goes to the planetarium (and a
  world without one refuses it), where "for" after a place is otherwise what they go there for."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import replace

from grove_tui.language.bare_place_names import bare_place_name
from grove_tui.language.lexicon import DEPARTURE_VERBS, PLACE_MODIFIERS, PLACE_SYNONYMS, START_OBJECT_VERBS
from grove_tui.language.moved_off_for import moved_off_for
from grove_tui.language.place_phrases import Place
from grove_tui.language.places import PlaceEntry, PlaceIndex, PlaceMatch
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import phrase_lemmas, verb_lemma


def avoided_places(index: PlaceIndex, said: list[Place], avoided: Place) -> list[str]:
    """The places a group must not use for the phrase `avoided`; when a place said before it in the
    clause (`said`, changed in place) is the same room, both are narrowed to the fixtures of that room
    their heads name ("the stairs" -> the stairwell, "the lifts" -> both elevators), when each names some
    and they are not the same."""
    if avoided.match is None:
        return []
    zone = avoided.match.name
    before = next((k for k in range(len(said) - 1, -1, -1) if said[k].match is not None), -1)
    prior = said[before].match if before >= 0 else None
    if avoided.match.kind != "zone" or prior is None or prior.name != zone:
        return [zone]
    taken, shunned = fixtures_named(index, zone, said[before].words), fixtures_named(index, zone, avoided.words)
    if not taken or not shunned or set(taken) & set(shunned):
        return [zone]
    e = taken[0]
    said[before] = replace(said[before], match=PlaceMatch(e.name, e.kind, e.zone, 1.0, False), score=1.0,
                           alternatives=(), reason=f"'{' '.join(said[before].words)}', not "
                                                   f"'{' '.join(avoided.words)}': {e.name} of {zone}")
    return [f.name for f in shunned]


def fixtures_named(index: PlaceIndex, zone: str, words: Sequence[str]) -> list[PlaceEntry]:
    """The fixtures of a room whose kind the phrase's head says, or a word of theirs that is not the
    room's own ("lift" is the elevators' kind by synonym; the lobby's bench is named after the lobby,
    not after lifts)."""
    content = [t for t in phrase_lemmas(list(words)) if t not in PLACE_MODIFIERS and t.isalpha()]
    room = index.entry(zone)
    if not content or room is None:
        return []
    head = content[-1]
    heads = {head}.union(*(group for group in PLACE_SYNONYMS if head in group))
    return [e for e in index.entries if e.zone == zone and e.kind == "entity"
            and heads & ({w for kind in e.types for w in kind.split()} | (e.tokens - room.tokens))]


def left_for(s: Sentence, said: Sequence[Place], at: int) -> bool:
    """Whether the "for" at `at` follows a place the clause's verb leaves ("leaves the auditorium for
    the planetarium", "quit the ward for the canteen") and comes with a determiner: the place after it
    is where they go ("leaves the office for lunch" is still what for)."""
    before = said[-1] if said else None
    if before is not None and moved_off_for(s, before, at):
        return True  # "heads off platform 2 for the signal box": where they go
    return before is not None and before.end == at and before.prep == "obj:start" and at + 1 < s.n \
        and (s.low[at + 1] in ("the", "this", "that") or bare_place_name(s.low, at + 1) > 0) \
        and verb_lemma(s.low[before.index]) in DEPARTURE_VERBS | START_OBJECT_VERBS
