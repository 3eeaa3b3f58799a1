"""A place said as a bare adverb, with no preposition (round 26): "sits quietly backstage", "a coach
stands rinkside", "a mum sits poolside", "the drummer heads backstage". A one-word adverb of place
("backstage", "rinkside", "pitchside") right after a verb (or its adverb of manner) that is a whole
name of one of the world's places is where people are, or where they go after a verb of going.

Round 51: a "-side" word the world has no alias for names the zone around the thing before "side"
("pitchside" where the world has a pitch), and one right after a person noun that ends a chat list's
item with no verb ("approx 40 skaters on ice, 3 marshals rinkside") is where those people are."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.bare_then_named import named_place_after
from grove_tui.language.lexicon import PERSON_NOUNS
from grove_tui.language.place_around import around
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import lemma, verb_lemma

_STAGE_WORDS = frozenset("backstage offstage onstage upstage downstage airside landside ashore aboard onboard".split())
_GOING = frozenset("walk run head go hurry dash nip pop slip come return rush stroll wander make race sprint "
                   "move scurry amble saunter troop file retreat disappear vanish".split())


def bare_place_at(s: Sentence, i: int) -> tuple[str, int] | None:
    """("at" or "to", 0) when the word at i is a bare adverb of place naming a place of the world."""
    word = s.low[i]
    if not (word in _STAGE_WORDS or len(word) > 6 and word.endswith("side") and word.isalpha()):
        return None
    if i > 0 and (s.low[i - 1] in lx.DETERMINERS or s.preposition(i - 1) is not None):
        return None  # "the poolside", "at rinkside": read as a phrase of its own
    match = s.index.match((lemma(word),))
    if match is None or not match.exact:
        match = around(s.index, (lemma(word),))  # "pitchside" in a world with a pitch: the pitch's zone
    if match is None or named_place_after(s, i, match.name):
        return None  # "waits backstage in the green room": the room said after it is where they are
    if item_person_before(s, i):
        return "at", 0  # "40 skaters on ice, 3 marshals rinkside": a chat list's item with no verb
    v = i - 1
    while v > 0 and (s.low[v].endswith("ly") and s.w[v].pos == "ADV" or s.low[v] in ("quietly", "nervously")):
        v -= 1  # "sits quietly backstage"
    if v < 0 or not (s.w[v].pos == "VERB" or verb_lemma(s.low[v]) in lx.INTENT_VERBS):
        return None
    return ("to" if verb_lemma(s.low[v]) in _GOING else "at"), 0


def item_person_before(s: Sentence, i: int) -> bool:
    """Whether the word before i is a person noun and the word at i ends its clause or list item
    ("3 marshals rinkside", "2 lifeguards poolside, ...")."""
    if i < 1 or s.lemma(i - 1) not in PERSON_NOUNS and lemma(s.low[i - 1]) not in PERSON_NOUNS:
        return False
    return i + 1 >= s.n or s.is_punct(i + 1) or s.low[i + 1] in ("and", "&")
