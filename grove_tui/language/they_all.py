"""A sequel said of every group before it: "4 people wait in the kitchen and 2 in meeting room 1; then
they all walk to reception". The words after the last group are its own (groups.py), so it alone would
go; "they all", "all of them", "both of them" say the groups of its sentence go too, each from where it
is to the place said, as one group does with "then they walk to reception"."""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import replace

from grove_tui.language.model import GroupReading
from grove_tui.language.sentence import Sentence

_ALL_OF_THEM = re.compile(r"\b(?:they\s+(?:all|both)|all\s+of\s+them|both\s+of\s+them|they\s+each)\b", re.IGNORECASE)


def all_go_on(s: Sentence, read: Sequence[GroupReading]) -> tuple[GroupReading, ...]:
    """The groups, those before a group whose words go on with "they all ..." to a place given it too."""
    out = list(read)
    sentences: list[int | None] = []
    pos = 0
    for g in read:
        at = s.prompt.find(g.text, pos) if g.text else -1
        sentences.append(_sentence_at(s, at) if at >= 0 else None)
        pos = at + len(g.text) if at >= 0 else pos
    for k, g in enumerate(read):
        said = _ALL_OF_THEM.search(g.text)
        if said is None or g.destination is None or sentences[k] is None or g.relation is not None or \
                _ALL_OF_THEM.search(g.who):  # "..., then both of them go": a group of its own, read as such
            continue
        j = k - 1
        while j >= 0 and sentences[j] == sentences[k] and out[j].relation is None and out[j].destination is None:
            out[j] = replace(out[j], destination=g.destination)
            j -= 1
    return tuple(out)


def _sentence_at(s: Sentence, char: int) -> int | None:
    return next((w.sentence for w in s.w if w.start <= char < w.end), None)
