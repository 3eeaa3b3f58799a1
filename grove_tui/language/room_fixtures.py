"""Fixtures and their rooms in a place phrase, for language/place_phrases.py: a fixture named after
the room it is in ("the toy shop's till", "the café's counter"), and several fixtures alike of one room
named in the plural, which are that room ("the luggage carousels", "the ticket gates")."""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language.place_ordinals import ordinal_place
from grove_tui.language.places import PlaceMatch
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import phrase_lemmas


def fixture_of_room(s: Sentence, k: int, j: int) -> PlaceMatch | None:
    """"the toy shop's till", "the café's counter": a fixture named after the room it is in, the
    room's name, a possessive, then the fixture's words, read among that room's fixtures."""
    mark = next((x for x in range(k + 1, j) if s.low[x] in ("'s", "’s")), None)
    if mark is None:
        return None
    said = phrase_lemmas(s.low[k:mark])
    ranked = ordinal_place(s.index, said)  # "the fourth gate's seats": the fourth gate's (round 69)
    room = ranked[0] if ranked is not None else s.index.match(said)
    thing = phrase_lemmas(s.low[mark + 1:j])
    if room is None or room.kind != "zone" or not thing:
        return None
    inside = [m for m in s.index.candidates(thing) if m.kind == "entity" and m.zone == room.name]
    # the room said decides it (round 69): "the second platform's bench" is platform 2's, though its words
    # are no whole name of the bench
    return PlaceMatch(inside[0].name, "entity", room.name, 1.0, True) if inside else None


def fixtures_as_room(s: Sentence, k: int, j: int, lemmas: Sequence[str], match: PlaceMatch | None) -> PlaceMatch | None:
    """"the luggage carousels", "the ticket gates": several fixtures alike of one room, named in the
    plural, are that room (not "one of the benches", which is one of them; the caller keeps "sit on
    the benches" on them)."""
    if match is None or match.kind != "entity" or j <= k or s.w[j - 1].tag != "NNS" or \
            (k >= 2 and s.low[k - 1] == "of" and s.low[k - 2] in ("one", "each", "any", "some")):
        return match
    alike = [m for m in s.index.candidates(lemmas) if m.kind == "entity" and m.zone == match.zone
             and m.score >= match.score - 1e-9 and _of_kind(s, m.name, lemmas[-1] if lemmas else "")]
    return PlaceMatch(match.zone, "zone", match.zone, match.score, False) if len(alike) >= 2 else match


def _of_kind(s: Sentence, name: str, head: str) -> bool:
    """Whether a fixture is of the kind the head says (its type or a word of its names): "the banqueting
    tables" are alike only with other tables of the room, not with its stage (its "top table"), when the
    room has things of that type."""
    entry = s.index.entry(name)
    typed = any(head in t.split() for e in s.index.entries if e.kind == "entity" and entry is not None and
                e.zone == entry.zone for t in e.types)  # the room has things of that type: by type alone
    return entry is not None and (any(head in t.split() for t in entry.types) or not typed and head in entry.tokens)


def room_fixture_said(s: Sentence, k: int, j: int) -> tuple[PlaceMatch, tuple[PlaceMatch, float, str, tuple[str, ...]]] | None:
    """fixture_of_room, decided (round 69), when the words before "'s" are a room's whole name or alias
    and the room has one thing of the words after it ("the south concourse's bar" where other rooms have
    bars too): the room said chooses, so meaning is not asked again; the match and its decision."""
    mark = next((x for x in range(k + 1, j) if s.low[x] in ("'s", "’s")), None)
    if mark is None:
        return None
    said = phrase_lemmas(s.low[k:mark])
    room = s.index.match(said)
    entry = s.index.entry(room.name) if room is not None and room.exact and room.kind == "zone" else None
    if entry is None or tuple(said) not in entry.phrases:
        return None  # "the women's toilet", "the manager's office": an owner, no room's name
    inside = [m for m in s.index.candidates(phrase_lemmas(s.low[mark + 1:j])) if m.kind == "entity" and m.zone == entry.name]
    if not inside or len(inside) > 1 and inside[1].score >= inside[0].score - 1e-9:
        return None  # "the food court's counter" of several counters there: not decided by the room
    found = PlaceMatch(inside[0].name, "entity", entry.name, 1.0, True)
    return found, (found, 1.0, f"'{' '.join(s.low[k:j])}': the {found.name} of {entry.name}, the room said", ())
