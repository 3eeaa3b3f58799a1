"""A place referred back to by "it" after more than "in" (round 37): "the cast of 14 on it escape" (a
stage, a stand, a platform said just before: people on it are in that room), "the 35 riders queuing for
it hurry out" (a ride said before: they stand in its queue). "on it" is a room only after a word for
the people on it ("the cast of 14 on it", "everyone on it") and when the place said before is a room,
never a thing ("a cup on it"); "for it" is a place only after a verb of queueing."""

from __future__ import annotations

from typing import TYPE_CHECKING

from grove_tui.language.place_pronouns import IT_PREPOSITIONS, referred_back
from grove_tui.language.place_queues import queue_of, queue_zone_for, queued_for
from grove_tui.language.place_search import searched_for
from grove_tui.language.places import PlaceMatch

from grove_tui.language.sentence import Sentence

if TYPE_CHECKING:
    from grove_tui.language.place_phrases import PlacePhrases

# Prepositions after which "it" may stand for a place said before, beyond IT_PREPOSITIONS.
_MORE = frozenset({"on", "for"})
# Words for people that may stand before "on it" though no noun: "everyone on it", "those on it".
_PEOPLE_WORDS = frozenset({"everyone", "everybody", "those", "all", "anyone", "anybody", "people"})


def may_be_place(s: Sentence, k: int, prep: str, at: int) -> bool:
    """Whether the "it" at word k, after the preposition at `at`, may be a place said before."""
    if s.low[k] != "it":
        return False
    if prep in IT_PREPOSITIONS:
        return True
    if prep not in _MORE or at < 1 or s.low[at] != prep:
        return False
    if k + 1 < s.n and not (s.is_punct(k + 1) or s.w[k + 1].pos in ("VERB", "AUX", "CCONJ", "ADP", "ADV")):
        return False  # "on it all", "for it one by one"? no: "it" then a noun is no pronoun of a place
    if prep == "on":
        before = s.w[at - 1]
        return before.pos in ("NOUN", "PROPN", "NUM") or s.low[at - 1] in _PEOPLE_WORDS
    return True


def pronoun_place(places: PlacePhrases, k: int, prep: str, at: int) -> tuple[tuple[PlaceMatch, float, str, tuple[str, ...]], int] | None:
    """The place "it" stands for after `prep`: the place said before (a room after "on"), its queue
    after a verb of queueing with "for"; None when it is none."""
    found = referred_back(places, k, at)
    if found is None or prep in IT_PREPOSITIONS:
        return found
    (match, score, reason, alternatives), end = found
    if prep == "on":
        return found if match.kind == "zone" else None
    queued = queue_zone_for(places.s, at, end, match)
    if queued is not None:
        return (queued[0], score, f"{reason}; {queued[1]}", alternatives), end
    own = match.kind == "zone" and queue_of(places.s.index, match.name) == match.name
    return found if own and queued_for(places.s, at, end) else None  # "queuing for it": the queue said before


def searched_or_queued_for(s: Sentence, i: int) -> bool:
    """Whether the "for" at word i opens a place: searched for ("look for the toilets"), or "it" after a
    verb of queueing ("queuing for it")."""
    return searched_for(s, i) or i + 1 < s.n and s.low[i + 1] == "it" and queued_for(s, i, i + 2)
