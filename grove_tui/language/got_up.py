"""People who get up and do something at a place go there (round 29): "of the nine sat in the waiting
room, a pair get up and pay at reception", "two shoppers get up and order at the coffee counter". The
verb after "get up and" is often one the lexicon lacks, so the place after it was read as where they
stay; getting up says they leave where they sat, so it is where they walk to. A verb of staying or
queuing after it ("get up and queue at the desk", "stand up and wait by the door") keeps its reading."""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import replace

from grove_tui.language import lexicon as lx
from grove_tui.language.model import GroupReading
from grove_tui.language.tokens import verb_lemma

_UP_AND = re.compile(r"\b(?:get|gets|getting|got|stand|stands|standing|stood|jump|jumps|hop|hops)\s+up\s+and\s+"
                     r"(?P<verb>[a-z]+)(?P<rest>.*)", re.IGNORECASE)
_STAYING = frozenset(("wait", "queue", "converse", "robot"))


def _names_place(rest: str, place: str) -> bool:
    words = set(re.findall(r"[a-z0-9]+", rest.lower()))
    parts = [p for p in place.lower().split("_") if p not in ("the", "of")]
    return bool(parts) and all(p in words or p + "s" in words for p in parts)


def got_up_and_went(read: Sequence[GroupReading]) -> tuple[GroupReading, ...]:
    """The groups, with one that gets up and does something at a place walking there (module doc)."""
    out: list[GroupReading] = []
    for g in read:
        m = _UP_AND.search(g.text)
        if m is not None and g.intent == "wait" and g.location is not None and g.destination is None \
                and lx.INTENT_VERBS.get(verb_lemma(m.group("verb").lower())) not in _STAYING \
                and _names_place(m.group("rest"), g.location):
            g = replace(g, intent="walk", destination=g.location, location=None, wait_seconds=None,
                        confidence=tuple(c for c in g.confidence if c.field not in ("intent", "destination", "location")))
        out.append(g)
    return tuple(out)
