"""Where people are served inside a room: "a woman queuing to pay in the café", "two guests wait to be
served in the bar", "a man queues to pay for his shopping at the supermarket". The room said holds a
counter, till or desk people are served at (tagged for service or a queue); someone there to pay, to be
served or to order stands at it, not anywhere in the room.

Round 72: a room that is itself a kiosk or booth ("lined up at the tobacco kiosk to buy cigarettes", "queue
at the chip kiosk to buy chips") is the serving place said: people queue at it, named as it is.
"""

from __future__ import annotations

import re

from grove_tui.language.places import PlaceEntry, PlaceIndex

# A purpose done at a room's serving fixture: paying, being served, ordering, checking out.
_SERVED = re.compile(r"^(?:to |in order to |so as to )?(?:pay|be served|get served|order|check ?out|buy|purchase)\b")
# What a fixture people are served at is called ("counter", "till", "checkout", "desk", "bar").
_SERVING_WORDS = frozenset("counter till checkout desk cashier cash bar kiosk window".split())
# Kinds of room that are themselves where people are served.
_SELF_SERVING = frozenset({"kiosk", "booth"})


def served_fixture(index: PlaceIndex, purpose: str | None, location: str | None) -> str | None:
    """The fixture of the room `location` where a purpose of paying or being served is done, when the
    room has one clearly (the first of tills alike); None otherwise."""
    if not purpose or not location or not _SERVED.match(purpose.lower().strip()):
        return None
    room = index.entry(location)
    if room is None or room.kind != "zone" or room.types & _SELF_SERVING:
        return None
    fixtures = [e for e in index.entries if e.kind == "entity" and e.zone == room.name and _serves(e)]
    if not fixtures:
        return None
    kinds = {frozenset(e.tokens & _SERVING_WORDS) for e in fixtures}
    if len(fixtures) > 1 and len(kinds) > 1 and not all(k & {"till", "checkout"} for k in kinds):
        return None  # a reception desk and a concierge desk: which one is not said
    return fixtures[0].name


def _serves(entry: PlaceEntry) -> bool:
    """Whether people are served at a fixture: called a counter, till or desk, and tagged for a queue."""
    return bool(entry.tokens & _SERVING_WORDS) and "queue" in entry.tag_tokens | entry.tokens
