"""A room said by what is done there when the embedding model does not know the trade ("the room where film
gets developed"): the clause's words are looked for in each room's own text (its description, its
fixtures' names and descriptions: the darkroom's "developing sinks"). When exactly one room of those
the head can be says more of them than any other, and the room read by meaning says none, that room is
meant; the meaning model alone ranks "develop film" nearest the painting studios."""

from __future__ import annotations

import re
from collections.abc import Sequence
from functools import lru_cache

from grove_tui.language.place_described import content_words
from grove_tui.language.places import PlaceIndex, PlaceMatch
from grove_tui.language.tokens import lemma, verb_lemma


def _stem(word: str) -> str:
    """A word without its ending, so that "developing", "developed" and "develop" are one."""
    for suffix in ("ing", "ed", "es", "s"):
        if word.endswith(suffix) and len(word) - len(suffix) >= 4:
            word = word[:-len(suffix)]
            break
    return word[:-1] if word.endswith("e") and len(word) >= 4 else word


def _words(text: str) -> set[str]:
    return {_stem(verb_lemma(lemma(w))) for w in re.findall(r"[a-z]+", text.lower())}


@lru_cache(maxsize=64)  # one index per world: its rooms' words are read once, not at every such clause
def _zone_words(index: PlaceIndex) -> dict[str, frozenset[str]]:
    """Each zone's words: its own text and its fixtures' names and descriptions, stemmed."""
    said: dict[str, set[str]] = {}
    for e in index.entries:
        if e.kind != "door":
            said.setdefault(e.zone, set()).update(_words(e.description) | _words(" ".join(e.said)))
    return {zone: frozenset(words) for zone, words in said.items()}


def room_saying_words(index: PlaceIndex, activity: str, meant: PlaceMatch,
                      kinds: Sequence[str] | None) -> PlaceMatch | None:
    """The zone whose own text alone holds the most of the activity's words, when the place `meant`
    says none of them; None otherwise."""
    content = {_stem(w) for w in content_words(activity)}
    if not content:
        return None
    said = _zone_words(index)
    allowed = set(kinds) if kinds is not None else None
    words = re.findall(r"[a-z]+", activity.lower())
    # the verb done there ("you wedge clay": "wedge") weighs more than the thing it is done to
    verb = {_stem(verb_lemma(lemma(words[x + 1])))} if "you" in words and (x := words.index("you")) + 1 < len(words) \
        else set()
    counts = sorted(((len(verb & text), len(content & text), zone) for zone, text in said.items()
                     if allowed is None or zone in allowed), reverse=True)
    if not counts or counts[0][1] == 0 or (len(counts) > 1 and counts[1][:2] == counts[0][:2]):
        return None
    mine = said.get(meant.zone, frozenset())
    if verb & mine or (not verb & said[counts[0][2]] and content & mine):
        return None
    zone = index.entry(counts[0][2])
    if zone is None or zone.kind != "zone":
        return None
    return PlaceMatch(zone.name, zone.kind, zone.zone, meant.score, False)
