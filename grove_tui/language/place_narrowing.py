"""When a fixture said in a clause may stand for the zone named in the same role. A fixture read only by
meaning, from words that name no place of the world ("in a wheelchair" read as the rinkside seating, like
"chair"; "pay in a cheque" as the paying-in machine, like "cheque machine"), does not narrow a zone named
by its own name ("from rinkside", "from the cashpoints lobby"): the zone said is where they are."""

from __future__ import annotations

from grove_tui.language.place_phrases import Place

# A place read below this, and not by a whole name, was read by meaning alone: a guess.
GUESS = 0.6


def guessed_over_named(fixture: Place | None, zone: Place | None) -> bool:
    """Whether `fixture` is a guess by meaning and `zone` was named by its whole name, surely."""
    return fixture is not None and zone is not None and fixture.match is not None and zone.match is not None and \
        not fixture.match.exact and fixture.score < GUESS and zone.match.exact and zone.score >= 1.0 and \
        zone.match.kind == "zone"
