"""A purpose that is a service done to a thing of one's own (round 44): "to get his prescription
filled", "to have her passport stamped", "to get his bag checked". The purpose is done where the room
serves people in turn, its one fixture people queue at (the pharmacy counter, the passport desk),
though a kiosk of the room is described with the same thing ("where prescriptions are handed in")."""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language.places import PlaceIndex, PlaceMatch

_HAVING = frozenset({"get", "gets", "getting", "have", "has", "having"})
_IRREGULAR_DONE = frozenset("done seen made sent fixed set cut shown given taken".split())


def service_done(words: Sequence[str]) -> bool:
    """Whether a purpose's words ("get his prescription filled") are having a thing done: "get" or
    "have", a thing, then a past participle."""
    return len(words) >= 3 and words[0] in _HAVING and (words[-1].endswith("ed") or words[-1] in _IRREGULAR_DONE) \
        and words[1] not in ("to", "up", "out", "in", "back")


def served_point(index: PlaceIndex, match: PlaceMatch) -> PlaceMatch:
    """The one fixture of the matched place's room that people queue at to be served, else the match."""
    points = [e for e in index.entries if e.kind == "entity" and e.zone == match.zone and
              {"queue", "service"} <= e.tag_tokens]
    if len(points) != 1:
        return match
    return PlaceMatch(points[0].name, "entity", points[0].zone, match.score, False)
