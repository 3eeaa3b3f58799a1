"""A fixture said as it is written, against its room said in another number (round 27): "wait in line at
the till" names the till counter, whose own name is "till", not the tills, whose name is the plural,
though both are "till" once lemmatised. A phrase written exactly as one fixture's name or alias, and
as none of its room's, is that fixture."""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language import lexicon as lx
from grove_tui.language.places import PlaceIndex, PlaceMatch


def said_in_number(index: PlaceIndex, phrase: Sequence[str], match: PlaceMatch) -> PlaceMatch:
    """The fixture of the zone `match` whose written name is the phrase as said, when the zone's own
    names are not; `match` otherwise."""
    if match.kind != "zone":
        return match
    text = _bare(" ".join(w for w in phrase if w.lower() not in lx.DETERMINERS))
    zone = index.entry(match.name)
    if not text or zone is None or text in {_bare(x) for x in zone.said}:
        return match  # "x ray" is the room's "X-ray", however it is spelt
    fixtures = [e for e in index.entries if e.kind == "entity" and e.zone == match.name
                and text in {_bare(x) for x in e.said}]
    if len(fixtures) != 1:
        return match
    return PlaceMatch(fixtures[0].name, "entity", fixtures[0].zone, match.score, True)


def _bare(text: str) -> str:
    """A name as letters and digits only: "X-ray", "x ray" and "xray" alike."""
    return "".join(ch for ch in text.lower() if ch.isalnum())
