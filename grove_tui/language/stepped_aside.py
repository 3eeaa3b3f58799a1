"""A step back or aside in place, away from the robot: "an intern at the printer steps back as the robot
passes", "a porter by the lifts moves aside", "a student at the desk edges back". Stepping is a verb of
going, so the place said with the person was read as where they set off from; but a step back or aside
goes nowhere: with no place to go to, the person stays where they are, and that place is their
location, not a start. Only for a group avoiding the robot with a start and nothing else."""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import replace

from grove_tui.language.model import GroupReading

_IN_PLACE = re.compile(r"\b(?:step|steps|stepped|stepping|move|moves|moved|moving|edge|edges|edged|edging|shuffle|"
                       r"shuffles|shuffled|shuffling|lean|leans|leaned|leant|leaning|sidle|sidles|sidled)\s+"
                       r"(?:\w+ly\s+)?(?:back|aside|backwards|sideways|out\s+of\s+the\s+way)\b(?!\s+(?:to(?!\s+(?:let|make|allow|give)\b)|into|towards?|"
                       r"onto|out|inside|through|across|down|up|over|along)\b)", re.I)


def stepped_aside_in_place(groups: Sequence[GroupReading]) -> tuple[GroupReading, ...]:
    """Groups that step back or aside from the robot where they stand, located there (module doc)."""
    out: list[GroupReading] = []
    for g in groups:
        if g.robot_interaction == "avoid" and g.start is not None and g.destination is None and not g.via \
                and g.location is None and _IN_PLACE.search(g.text or ""):
            g = replace(g, start=None, location=g.start)
        out.append(g)
    return tuple(out)
