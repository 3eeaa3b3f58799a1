"""The outdoors past the doors, and the site places a world may lack (round 52). "Out to the street",
"leave through the booking hall to the street", "walk out of the cafeteria to the car park": people
leave, out through the exit nearest the scene (place_phrases.py). But a car park is a place of a site
like any other: "head from the foyer across to the car park", with no leaving said and no hazard, names
a place the world does not have, and is refused like any such place. The street or the road is past
the doors whatever is said."""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language import lexicon as lx
from grove_tui.language.hazards import said as hazard_said
from grove_tui.language.sentence import Sentence

# Outdoor words that name a place of the site, which a world may lack.
_SITE_PLACES = frozenset({"carpark", "car_park", "parking"})
# Words of leaving the building, in the clause before the place ("go out to", "leave ... to").
_LEAVING = frozenset("out outside outdoors leave leaves left leaving exit exits exited exiting evacuate evacuates "
                     "evacuated evacuating escape escapes escaped escaping flee flees fled fleeing".split())


def outdoors(lemmas: Sequence[str]) -> str | None:
    """The outdoor word a place phrase names past the doors ("the street", "the car park"), else None."""
    content = [t for t in lemmas if t not in lx.PLACE_MODIFIERS]
    if not content:
        return None
    if content[-1] in lx.OUTDOOR_WORDS:
        return content[-1]
    pair = "_".join(content[-2:])
    return pair if pair in lx.OUTDOOR_WORDS else None


def past_the_doors(s: Sentence, lemmas: Sequence[str], at: int) -> bool:
    """Whether a phrase after the preposition at `at` names the outdoors people go out to (module doc)."""
    word = outdoors(lemmas)
    if word is None:
        return False
    if word not in _SITE_PLACES:
        return True
    start = at
    while start > 0 and not s.is_punct(start - 1) and s.w[start - 1].sentence == s.w[at].sentence:
        start -= 1
    return any(s.low[k] in _LEAVING for k in range(start, at + 1)) or hazard_said(s) or \
        any(s.low[k] in lx.HAZARD_NOUNS or s.lemma(k) in lx.HAZARD_NOUNS for k in range(s.n))
