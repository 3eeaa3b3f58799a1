"""A thing pushed along from one place to another is no place of the mover's: "a postie wheels a roll cage
from the sorting office to the vans", "two porters push a bed into the lift". The world may name the thing
(the roll cages are fixtures of the sorting office), but the object of a verb of pushing that a "from",
"to" or "into" follows is what is moved, so where the walk starts and ends is said by the places after it
(round 49), not by the thing's own spot."""

from __future__ import annotations

from grove_tui.language.pushed_things import _PUSHING
from grove_tui.language.sentence import Sentence

_ALONG = frozenset({"from", "to", "into", "onto", "towards", "toward", "across", "along", "through", "out"})


def moved_along(s: Sentence, verb: str, obj: int) -> bool:
    """Whether the verb (a lemma) pushes its object, the phrase at `obj`, along to or from a place."""
    if verb not in _PUSHING or obj >= s.n:
        return False
    end = s.phrase_end(obj)
    return end < s.n and s.low[end] in _ALONG
