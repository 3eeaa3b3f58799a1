"""A zone people are named by and a place they are said to come from (round 51): "a bookie's clerk walks
from the champagne bar back to the betting ring", "the laundry's porter walks from the chapel to the kitchen".

The zone whose people the mention is ("the bookie's", "ward A's") says whom they belong to, and where
they are when nothing else says so; but a place said after "from" is where they set off, by
its whole name, so the possessor's zone is no place of theirs in that clause. A zone the mention is a
share of ("half the open office") is still where they are."""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language.mention import Mention
from grove_tui.language.place_phrases import Place

_FROM = frozenset({"from", "obj:start"})  # not "out": "file out by the side exit" is the way out


def kept_zone_place(m: Mention, places: Sequence[Place]) -> Place | None:
    """The mention's zone, kept as a place of its clause: always for a share of a zone ("half the open
    office"); for a possessor ("ward A's patients") only when the clause says no place they come from."""
    if m.zone_place is None or m.whole_zone:
        return m.zone_place
    said_from = any(p.prep in _FROM and p.match is not None and p.index > m.last for p in places)
    return None if said_from else m.zone_place
