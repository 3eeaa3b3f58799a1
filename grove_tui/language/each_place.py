"""People spread over every place of a kind: "two guards stand at each exit", "place one cleaner on
every platform", "three students in each of the seminar rooms". The group is read once, at the one
place its phrase names first; here it is given once per place of that kind the world has, each copy
as many as the sentence says ("two guards at each exit" in a station with four exits: four groups of
two; "Every platform has three passengers waiting"). The places are those the phrase's words fit best and alike (the index's tied best matches of the
chosen place's own kind: doors for "exit", zones for "seminar room"); with "in"/"of" after the phrase
("every table in the restaurant") only those inside the chosen place's room."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import replace

from grove_tui.language import lexicon as lx
from grove_tui.language.model import GroupReading
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import verb_lemma

_EACH = frozenset({"each", "every"})
_SKIPPED = frozenset({"of", "the", "single", "one", "its", "their"})
_MAX_PLACES = 12


def spread_over_each(s: Sentence, read: Sequence[GroupReading]) -> tuple[GroupReading, ...]:
    """The groups, each one said to be at (or go to) "each"/"every" place of a kind given once per
    such place; relations to later groups renumbered."""
    phrases = [p for p in (_each_phrase(s, i) for i in range(s.n) if s.low[i] in _EACH) if p is not None]
    if not phrases:
        return tuple(read)
    out: list[GroupReading] = []
    shift: dict[int, int] = {}
    for k, g in enumerate(read):
        shift[k] = len(out)
        copies = _copies(s, g, phrases)
        if len(copies) > 1:  # a phrase heading the clause ("Every exit has a guard") is its first group's only
            phrases = [p for p in phrases if p[0]]
        out.extend(copies)
    if len(out) == len(read):
        return tuple(read)
    return tuple(replace(g, relation=_renumbered(g.relation, shift)) for g in out)


def _each_phrase(s: Sentence, i: int) -> tuple[str, tuple[str, ...], bool] | None:
    """(the words from the preposition, the place words, whether "in"/"of" follows) of "at each
    exit", "on every platform", "in each of the seminar rooms"; None when "each" is no place's."""
    fronted = (i == 0 or s.is_punct(i - 1) or s.w[i - 1].sentence != s.w[i].sentence) and \
        any(verb_lemma(s.low[k]) == "have" for k in range(i + 1, min(i + 6, s.n)))  # "Every exit has a guard"
    after_preposition = i > 0 and (s.low[i - 1] in lx.PLACE_PREPOSITIONS or s.low[i - 1] in ("at", "on", "in", "by", "to"))
    if not (fronted or after_preposition):
        return None
    j = i + 1
    while j < s.n and s.low[j] in _SKIPPED:
        j += 1
    end = j
    while end < s.n and (s.w[end].pos in ("NOUN", "PROPN", "ADJ") or (end > j and s.w[end].pos == "NUM")):
        end += 1
    if end == j:
        return None
    words = tuple(s.lemma(k) for k in range(j, end))
    inside = end < s.n and s.low[end] in ("in", "of", "on", "at")
    return ("" if fronted else s.span(i - 1, end - 1).lower()), words, inside


def _copies(s: Sentence, g: GroupReading, phrases: Sequence[tuple[str, tuple[str, ...], bool]]) -> list[GroupReading]:
    text = g.text.lower()
    for said, words, inside in phrases:
        if said not in text:
            continue
        for field in ("location", "start", "destination"):
            chosen = getattr(g, field)
            places = _places_alike(s, words, chosen, inside)
            if len(places) > 1:
                confidence = tuple(c for c in g.confidence if c.field != field)
                return [_at(replace(g, confidence=confidence), field, p) for p in places]
    return [g]


def _at(g: GroupReading, field: str, place: str) -> GroupReading:
    """The group with one of its place fields set to `place`."""
    if field == "location":
        return replace(g, location=place)
    return replace(g, start=place) if field == "start" else replace(g, destination=place)


def _places_alike(s: Sentence, words: tuple[str, ...], chosen: str | None, inside: bool) -> list[str]:
    """The places the words fit best and alike, of the chosen place's kind, the chosen one first."""
    if chosen is None:
        return []
    found = s.index.candidates(list(words))
    mine = next((m for m in found if m.name == chosen), None)
    if mine is None:
        return []
    entry = s.index.entry(chosen)
    alike = [m.name for m in found if m.kind == mine.kind and abs(m.score - mine.score) < 1e-6 and (
        not inside or entry is None or (s.index.entry(m.name) or entry).zone == entry.zone)]
    if len(alike) > _MAX_PLACES:
        return []
    return [chosen, *(p for p in alike if p != chosen)]


def _renumbered(relation: str | None, shift: dict[int, int]) -> str | None:
    """"subset_of:2" after groups were spread: the index the group now has."""
    if relation is None:
        return None
    kind, _, index = relation.partition(":")
    return f"{kind}:{shift[int(index)]}" if index.isdigit() and int(index) in shift else relation
