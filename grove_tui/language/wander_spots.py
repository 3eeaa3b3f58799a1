"""Wandering needs room to wander in (round 44): "three or four schoolgirls mill about near the ticket
machines", "a couple of teenagers hang around by the vending machine", "two porters drift about beside the
lifts". Said of a thing, by a word of nearness ("near", "by", "beside", "next to", "outside", "in front of"),
the people stay at that spot: they wait there (a round or a chore there, "patrols near the fountain", still
goes about it). Said of a room or an area ("mill around the concourse",
"wander round the gallery"), or of a thing gone round or through ("browse the perfume shelves"), they
wander, as before.

Wandering with somewhere to go is walking there ("stroll to the café", "wander off to the clothes shop"),
except between shops (round 44): "a couple wander from the paint aisle over to lighting", "two teens drift
from the sports shop to the games shop". Going from one shop (or a shop's department) to another with no
errand said is browsing one's way round: they wander. From a shop to a café, a tunnel or a museum, or with
an errand ("... to pick up a day pass"), they walk. Round 70: so do those who go to a shop said by what is
there ("drift over from the cat aisle to where the snakes live"): a goal sought, no browsing.

A chore's word that is a thing's adjective ("carries clean linen to ward B", "the robot carries clean towels
from the laundry") is no chore: said after a verb or a determiner and before the noun it describes."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from grove_tui.language.place_phrases import Place
    from grove_tui.language.places import PlaceIndex
    from grove_tui.language.sentence import Sentence

# Verbs of going about that keep going round a thing, wherever it is said: a round or a chore ("a guard
# patrols near the fountain", "a cleaner sweeps by the bench"), not idling there.
SPOT_KEEPING_VERBS = frozenset("patrol pace tour explore mop sweep vacuum hoover scrub tidy clean".split())
# Words of nearness to a thing: where someone stands, not an area gone about in.
_NEAR = frozenset({"near", "by", "beside", "next", "outside", "alongside", "close", "front", "against", "at"})


def _said_near(s: Sentence, p: Place) -> bool:
    if p.prep.startswith("obj:") or p.index >= s.n:
        return False  # "browse the shelves": the thing gone over, no spot beside it
    word = s.low[p.index]
    if word == "in" and p.index + 1 < s.n and s.low[p.index + 1] == "front":
        return True
    return word in _NEAR


def wandering_at_a_spot(s: Sentence, places: Sequence[Place]) -> bool:
    """Whether a clause of wandering names only things (no room, area or door) and each by a word of
    nearness: the people stay at that spot (module doc)."""
    named = [p for p in places if p.match is not None and p.prep not in ("for", "purpose")]
    return bool(named) and all(p.match is not None and p.match.kind == "entity" and _said_near(s, p) for p in named)


# Kinds of zone people browse in: a shop, a store's department, a market's stalls.
_BROWSED = frozenset({"shop", "store", "department", "boutique", "market", "stalls", "showroom"})
_STARTS = frozenset({"from", "obj:start"})
_ENDS = frozenset({"to", "into", "towards", "toward", "onto", "obj:dest"})


def _browsed(index: PlaceIndex, p: Place) -> bool:
    entry = index.entry(p.match.name) if p.match is not None else None
    return entry is not None and entry.kind == "zone" and bool(entry.types & _BROWSED)


def browsing_between_shops(index: PlaceIndex, places: Sequence[Place], purpose: str | None) -> bool:
    """Whether a clause of wandering goes from one shop to another with no errand (module doc)."""
    if purpose:
        return False
    starts = [p for p in places if p.prep in _STARTS and p.match is not None]
    ends = [p for p in places if p.prep in _ENDS and p.match is not None]
    if any(p.words[:1] in (("where",), ("wherever",)) for p in ends):
        return False  # "drift over from the cat aisle to where the snakes live": a goal said by what is there
    return bool(starts) and bool(ends) and all(_browsed(index, p) for p in (*starts, *ends))


# Chores the lexicon reads as wandering over a room ("a cleaner mops the corridor").
CHORE_VERBS = frozenset("mop sweep vacuum hoover scrub tidy clean dust polish".split())


def chore_after_coming(candidates: Sequence[tuple[int, str, str]]) -> tuple[int, str, str] | None:
    """The verb of going said before a chore, when a clause says people come somewhere and then do the
    chore there ("the cleaners come in through the back door and mop the corridor", "two porters walk
    over from the lifts and sweep the foyer"): they walk there; the chore is what they go to do. None
    when the chore comes first or no verb of going comes before it."""
    chore = next((c for c in candidates if c[1] == "wander" and c[2] in CHORE_VERBS), None)
    if chore is None or any(c[1] == "wander" and c[2] not in CHORE_VERBS for c in candidates):
        return None
    return next((c for c in candidates if c[1] == "walk" and c[0] < chore[0]), None)


def thing_adjective(s: Sentence, i: int) -> bool:
    """Whether the word at i is an adjective of the thing after it, inside a verb's object ("carries clean
    linen"), not a verb ("Evacuate boarding area A1", "clean the corridor") (module doc)."""
    w = s.w[i]
    if w.pos != "ADJ" or w.dep != "amod" or w.head <= i or i == 0:
        return False
    prev = s.w[i - 1]
    return prev.pos in ("VERB", "DET", "ADJ", "NUM", "PRON") and not s.is_punct(i - 1)
