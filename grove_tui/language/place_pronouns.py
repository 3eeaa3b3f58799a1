"""A place referred back to by a pronoun (round 27): "a burst pipe floods the passenger lounge, and the
12 folk sheltering in it move out": "in it" is the place said last before it, the passenger lounge."""

from __future__ import annotations

from typing import TYPE_CHECKING

from grove_tui.language.places import PlaceMatch
from grove_tui.language.tokens import lemma, phrase_lemmas

if TYPE_CHECKING:
    from grove_tui.language.place_phrases import PlacePhrases

# Prepositions after which "it" is a place people are in ("sheltering in it"); not "at it", "after it",
# said of the robot as often as of a place ("stare at it as it passes").
IT_PREPOSITIONS = frozenset({"in", "inside", "within"})


def referred_back(places: PlacePhrases, k: int, at: int) -> tuple[tuple[PlaceMatch, float, str, tuple[str, ...]], int] | None:
    """The place "it" (word k, after the preposition at `at`) stands for: the last place said before it
    in the prompt, a room or a thing, not a door; None when none was said or the word is no pronoun
    of a place ("in it together")."""
    s = places.s
    if s.low[k] != "it" or (k + 1 < s.n and s.low[k + 1] in ("all", "together")):
        return None
    said = [(p.index, p.match) for p in places.history if p.match is not None and p.index < at and p.match.kind != "door"]
    named = _named_before(places, at)
    if named is not None:
        said.append(named)
    if not said:
        return None
    match = max(said, key=lambda p: p[0])[1]
    return (match, 0.8, f"'it': the place said before, {match.name}", ()), k + 1


def _named_before(places: PlacePhrases, at: int) -> tuple[int, PlaceMatch] | None:
    """The last phrase before word `at` that is a whole name of the world's room or thing, though no
    clause of people read it ("a burst pipe floods the passenger lounge")."""
    s = places.s
    for x in range(at - 1, -1, -1):
        if s.low[x] not in ("the", "a", "an"):
            continue
        phrase, end = places._words(x + 1)
        if not phrase or end > at:
            continue
        lemmas = tuple(phrase_lemmas(phrase)) or tuple(lemma(w) for w in phrase)
        if places.people.is_person_phrase(lemmas):
            continue
        match = s.index.match(lemmas)
        if match is not None and match.exact and match.kind != "door":
            return x, match
    return None
