"""People said by the queue they stand in, who then move (round 37): "the 35 riders queuing for it hurry
out via the east gate", "ten people lined up for the Viper walk to the food court". The queue said with
a participle on the people is where they are, so it is their start, not where they go; where they go is
the place said after their own verb ("via the east gate"), or none."""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import replace

from grove_tui.language.model import GroupReading
from grove_tui.language.place_queues import queue_of
from grove_tui.language.places import PlaceIndex
from grove_tui.language.purposed_places import place_named
from grove_tui.language.tokens import phrase_lemmas

# A participle of queueing on the people, its "for" and what is queued for, then the people's own verb.
_QUEUED = re.compile(r"\b(?:queu(?:e)?ing|lined\s+up|lining\s+up|waiting\s+in\s+line|standing\s+in\s+line|"
                     r"waiting\s+in\s+the\s+queue)(?:\s+\w+ly)?\s+for\s+(?P<what>it|(?:the\s+)?[\w'-]+(?:\s+[\w'-]+){0,2}?)"
                     r"\s+(?P<rest>\w+(?:\s+\w+)?\b.*)$", re.I)
# Prepositions after the people's own verb that say where they go.
_GOING = re.compile(r"\b(?:to|towards|toward|into|via|through|for)\s+(?P<place>(?:[\w'-]+\s*){1,5})", re.I)
_MOVING = frozenset({"walk", "evacuate"})


def queued_movers(index: PlaceIndex, groups: Sequence[GroupReading]) -> tuple[GroupReading, ...]:
    """Groups read as going to the queue they were said to stand in start there instead."""
    out: list[GroupReading] = []
    for g in groups:
        # (a start already said that is the queue itself, "Splash Falls shuts and the riders queuing for it ...")
        m = _QUEUED.search(g.text) if g.start is None or g.start == g.destination else None
        if m is None:
            pass
        elif g.intent in _MOVING and g.destination is not None and queue_of(index, g.destination) == g.destination:
            going = _GOING.search(m.group("rest"))
            to = place_named(index, going.group("place").split()) if going is not None else None
            g = replace(g, start=g.destination, destination=to if to != g.destination else None)
        elif g.intent in _MOVING and (queue := _queued_for(index, g.text[m.start("what"):])) not in (None, g.destination):
            g = replace(g, start=queue)  # "the riders queuing for Splash Falls hurry out via the east gate"
        elif g.intent == "queue" and g.location is not None and g.destination not in (None, g.location) and \
                queue_of(index, g.location) == g.location:
            g = replace(g, intent="walk", start=g.location, location=None)  # "lined up for it head to the café"
        out.append(g)
    return tuple(out)


def _queued_for(index: PlaceIndex, text: str) -> str | None:
    """The queue zone of the place named at the start of `text` ("Splash Falls hurry out"), or None."""
    words = [w.strip(".,;:!?").lower() for w in text.split()[:4]]
    words = words[1:] if words[:1] == ["the"] else words
    for end in range(len(words), 0, -1):
        match = index.match(tuple(phrase_lemmas(words[:end])))
        if match is not None and match.exact:
            return queue_of(index, match.zone)
    return None
