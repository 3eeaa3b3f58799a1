"""What they go for, said after "and" behind the place a "for" names (issue 29): "abandon their desks
for the boardroom and the weekly call", "quit the ward for the canteen and a late lunch". After a place
said with "for", an "and" whose phrase names no place of the world, no person and no verb is the
second thing "for" governs: not a next stop (a place there is still a route's next stop, read by the
sequel of clauses.py), but why they go there."""

from __future__ import annotations

from collections.abc import Callable, Collection, Sequence
from typing import TYPE_CHECKING

from grove_tui.language import lexicon as lx
from grove_tui.language.particle_ends import place_end

if TYPE_CHECKING:
    from grove_tui.language.place_phrases import Place
    from grove_tui.language.sentence import Sentence


def purpose_after_for_place(s: Sentence, places: Sequence[Place], i: int, own: Collection[int],
                            is_person: Callable[[int], bool], names_place: Callable[[int], bool]) -> int | None:
    """The end (exclusive) of the purpose that the "and" at i opens after a place said with "for", or None."""
    if s.low[i] != "and" or not places or i + 2 >= s.n:
        return None
    before = places[-1]
    if before.prep != "for" or before.match is None or place_end(s, before) != i:
        return None
    k = i + 1
    if s.low[k] not in ("a", "an", "the", "their", "his", "her", "our", "some") or k not in own:
        return None
    end = s.phrase_end(k + 1)
    if end <= k + 1 or any(s.w[x].pos in ("VERB", "AUX", "PRON", "NUM") or s.low[x] in lx.ROBOT_WORDS
                           or is_person(x) for x in range(k + 1, end)) or names_place(k) or names_place(k + 1):
        return None  # "and the nurses wait", "and the robot", "and the pharmacy": no purpose
    if s.w[end - 1].pos != "NOUN":
        return None
    return end
