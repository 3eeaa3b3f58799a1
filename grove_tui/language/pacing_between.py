"""Pacing between two places (round 33): "a guard paces between the shop and the café", "a porter
shuttles between the pharmacy and the ward", "a steward patrols up and down between gate 1 and gate 4",
"two cleaners roam back and forth between the toilets and the lobby". A verb of going about with no end,
said with "between" two places the world has, is going from the one to the other (a walk, like "walks
between ward A and ward B"), not staying about the first. Waiting or standing between two places
("waits between the fountain and the lifts") is no going at all and keeps its reading."""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import replace

from grove_tui.language.model import GroupReading
from grove_tui.language.places import PlaceIndex
from grove_tui.language.tokens import lemma

_PACING = re.compile(r"\b(?:pac|patroll?|shuttl|roam|wander|ply|plie|mooch|flit|bustl|commut|yo-yo|criss-cross)"
                     r"(?:e|es|ed|ing|s|ling|led|les|le)?\b", re.I)
_BETWEEN = re.compile(r"\bbetween\s+(.+?)\s+and\s+(.+)$", re.I)
_STOPS = frozenset("in on at by near to from with for while as and then before after until , . ; : !".split())
_DETERMINERS = frozenset("the a an that this their our its his her".split())


def _place(index: PlaceIndex, words: Sequence[str], whole: bool = False) -> str | None:
    phrase: list[str] = []
    for w in words:
        bare = w.strip(".,;:!?").lower()
        if not bare or (bare in _STOPS and phrase and not whole):
            break
        if not phrase and bare in _DETERMINERS:
            continue
        phrase.append(bare)
        if w != bare and w.lower() != bare:  # punctuation ends the phrase
            break
    for end in range(len(phrase), 0, -1):
        found = index.match([lemma(x) for x in phrase[:end]])
        if found is not None and found.exact:
            return found.name
    return None


def _second(index: PlaceIndex, text: str) -> str | None:
    words = text.split()
    return _place(index, words) if words else None


def pacing_between(index: PlaceIndex, groups: Sequence[GroupReading]) -> tuple[GroupReading, ...]:
    """Groups that pace between two places walk from the first to the second (module doc)."""
    out: list[GroupReading] = []
    for g in groups:
        pace = _PACING.search(g.text)
        m = _BETWEEN.search(g.text[pace.end():]) if pace is not None and g.intent in ("wander", "wait") else None
        if m is not None and pace is not None:
            first = _place(index, m.group(1).split(), whole=True)  # "between goods in and ...": the whole
            second = _second(index, m.group(2))
            if first is not None and second is not None and first != second and g.location in (None, first, second):
                g = replace(g, intent="walk", start=first, destination=second, location=None, wait_seconds=None)
        out.append(g)
    return tuple(out)
