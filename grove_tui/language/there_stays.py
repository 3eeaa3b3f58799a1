"""People said to be "there" where they stay ("the forty-odd commuters standing there", "the people
there", "the shoppers waiting there"): "there" is the place said just before it, and it is where they
are, so where they start when they are then moved (or where they stay). The general "there" reading
(groups) took a "there" not after a preposition as where people go, and so, with a route already read,
dropped it; a place said with "along" before it was kept only as a place passed through."""

from __future__ import annotations

from typing import TYPE_CHECKING

from grove_tui.language import lexicon as lx
from grove_tui.language.tokens import verb_lemma

if TYPE_CHECKING:
    from grove_tui.language.place_phrases import PlacePhrases
    from grove_tui.language.roles import Roles

# Verbs of staying put, said as a participle before "there" ("standing there", "sheltering there").
_STAYING = lx.ROBOT_WAIT_VERBS | frozenset("queue gather huddle shelter crowd cluster sit stand work shop "
                                           "browse mill loiter camp".split())


def _stays_there(places: PlacePhrases, span: tuple[int, int]) -> int | None:
    """Where in the span "there" says where the people are: after a participle of staying or right
    after the people's noun ("the people there"), even before "are": no existential "there are" then."""
    s = places.s
    for x in range(span[0] + 1, span[1]):
        if s.low[x] != "there":
            continue
        prev = s.low[x - 1]
        if (prev.endswith("ing") or prev in ("sat", "stood", "seated", "gathered")) and verb_lemma(prev) in _STAYING:
            return x
        if s.w[x - 1].pos == "NOUN" and x + 1 < s.n and s.w[x + 1].pos in ("VERB", "AUX"):
            return x
    return None


def stayed_there(places: PlacePhrases, span: tuple[int, int], roles: Roles, stationary: bool) -> bool:
    """Place the group at the place said before a "there" of staying: where they stay, or where they
    start when they move (no longer only a place passed). True when it was read."""
    at = _stays_there(places, span)
    if at is None:
        return False
    before = [p for p in places.history if p.index < at and p.match is not None and p.match.kind != "door"]
    said = max(before, key=lambda p: p.index, default=None)  # the history is not in the sentence's order
    if said is None or said.match is None:
        return False
    name = said.match.name
    role = "location" if stationary else "start"
    if role == "start" and roles.location == name and roles.start is None and roles.destination is not None:
        roles.location = None  # "the visitors gathered there are taken out": gathered there, then moved
    if getattr(roles, role) not in (None, name) or name in (roles.destination, roles.location if role == "start" else None):
        return False
    if getattr(roles, role) is None:
        setattr(roles, role, name)
        roles.via = [v for v in roles.via if v != name]
        roles.read_from.setdefault(name, said)
    return True
