"""One person who hears an alarm and hurries to a room is answering it, not fleeing: "hearing the alarm, a
lifeguard leaves the stand and hurries to the treatment room", "when the alarm sounds, the duty manager
runs to the control room". An alarm is an evacuation cue (hazards.py), but people fleeing go out: to an
exit, outdoors, a corridor or a place of safety, or nowhere said. A lone person sent by an alarm to an
inner room (or a thing in one) is called to a job there; they walk. Several people, a verb of getting
out ("evacuate", "escape", "get out") or a refuge as the destination keep the evacuation."""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import replace

from grove_tui.language.model import GroupReading
from grove_tui.language.places import PlaceIndex

# Words of a place people flee to: outdoors, the ways out, the halls they are led along, a muster point.
_REFUGE = frozenset(
    "exit exits door gate entrance outside outdoor outdoors garden lawn yard terrace car park parking street "
    "corridor hallway hall lobby foyer concourse stair stairs stairway staircase landing assembly muster "
    "refuge safe safety shelter evacuation escape forecourt square patio courtyard field pitch".split())
_GETTING_OUT = re.compile(
    r"\b(?:evacuat\w*|escap\w*|flee\w*|fled|get(?:s|ting)?\s+out|got\s+out|clear(?:s|ing|ed)?\s+out|"
    r"empt(?:y|ies|ied)|pour(?:s|ing)?\s+out|file(?:s|d)?\s+out|run(?:s|ning)?\s+out|rush(?:es|ing)?\s+out|"
    r"outside|out\s+of\s+the\s+building|to\s+safety)\b", re.I)


def answering_alarms(index: PlaceIndex, groups: Sequence[GroupReading]) -> tuple[GroupReading, ...]:
    """Groups evacuating on an alarm that are one person hurrying to an inner room: walking there."""
    return tuple(replace(g, intent="walk") if _answers(index, g) else g for g in groups)


def _answers(index: PlaceIndex, g: GroupReading) -> bool:
    if g.intent != "evacuate" or g.destination is None or g.count.kind not in ("exact", "implied") or g.count.value != 1:
        return False
    if _GETTING_OUT.search(g.text or ""):
        return False
    entry = index.entry(g.destination)
    if entry is None or entry.kind == "door" or entry.exit:
        return False
    zone = index.entry(entry.zone) if entry.kind != "zone" else entry
    words = entry.tokens | entry.tag_tokens | (zone.tokens | zone.tag_tokens if zone is not None else frozenset())
    return not words & _REFUGE
