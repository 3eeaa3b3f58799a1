"""A fixture called by its own whole name beats the room that has that name only as an alias (round
53): in a DIY store whose trade counter is also called "the trade desk", "queuing at the trade desk" is
at the desk the world names trade_desk, not merely in the room. Both answer the phrase equally well;
the room wins such ties (`PlaceIndex.match`) unless the phrase is, word for word, the fixture's own
name of two words or more and not the room's own name ("the bar" stays the bar, not its "bar" counter).
"""

from __future__ import annotations

from collections.abc import Sequence


def names_the_fixture(phrase: Sequence[str], fixture_name: Sequence[str], zone_name: Sequence[str]) -> bool:
    """Whether the phrase is the fixture's own name of two or more words and not its room's own name."""
    said = tuple(t for t in phrase if t)
    return len(fixture_name) >= 2 and said == tuple(fixture_name) and said != tuple(zone_name)
