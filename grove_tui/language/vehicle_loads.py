"""A vehicle said for what it holds (round 33): "a minibus of pensioners from Leeds", "a coachful of
day-trippers", "a van full of roadies" are as many people as the vehicle carries, as "a minibusload",
"a coachload" already were (lexicon COLLECTIVE sizes). Read as written, the vehicle was one person
and the people in it were lost. Written as its load word before the reader parses it, not when "the"
or "a" follows "of" ("a coach of the under-12s" is a person)."""

from __future__ import annotations

import re

_VEHICLE_LOAD = {"minibus": "minibusload", "coach": "coachload", "bus": "busload", "van": "vanload",
                 "car": "carload", "boat": "boatload", "plane": "planeload", "train": "trainload"}
_VEHICLE = re.compile(r"\b(a|an|one|another|the|our|their|whole)\s+(minibus|coach|bus|van|car|boat|plane|train)"
                      r"(?:ful|\s+full|\s+load)?\s+of\s+(?!(?:the|a|an|this|that|his|her|my|our|their|its)\b)(?=[a-z])",
                      re.IGNORECASE)


def with_vehicle_loads(text: str) -> str:
    """The text with a vehicle said for its load written as the load word (module doc)."""
    return _VEHICLE.sub(lambda m: f"{m.group(1)} {_VEHICLE_LOAD[m.group(2).lower()]} of ", text)
