"""A place said by what is done there, gone to from a place said before it, is another place: in "walk
from the pro shop to where members hit buckets of practice balls" the clause's words are near the shop's
balls on display by meaning, but people going *from* the shop *to* it go somewhere else. When the
meaning's choice is the very room they set off from (a fixture in it may be gone to: "from the foyer
to where ushers sell popcorn" is its counter) and it had a near alternative elsewhere, the alternative
is the place meant (a fixture read as its room where a room of its own says it)."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

from grove_tui.language import lexicon as lx
from grove_tui.language.places import PlaceIndex, PlaceMatch
from grove_tui.language.tokens import lemma

if TYPE_CHECKING:
    from grove_tui.language.place_phrases import Place
    from grove_tui.language.sentence import Sentence


def left_zone(s: Sentence, history: Sequence[Place], at: int) -> str | None:
    """The zone of the place said with "from" before `at` in its sentence, none with a clause break
    between (a full stop, a comma, a clause starter)."""
    for p in reversed(history):
        if p.index >= at or p.match is None or s.w[p.index].sentence != s.w[at].sentence:
            continue
        if p.written != "from" and p.prep != "from":
            return None
        if any(s.is_punct(j) or s.low[j] in lx.CLAUSE_STARTERS for j in range(p.end, at)):
            return None
        return p.match.zone
    return None


def elsewhere(index: PlaceIndex, s: Sentence, history: Sequence[Place], prep: str, at: int, said: Sequence[str],
              match: PlaceMatch, alternatives: Sequence[str], reason: str) -> tuple[PlaceMatch, tuple[str, ...], str] | None:
    """Another place than the room they left, when `match` (gone to by a "where" clause) is that room
    and the meaning's alternative elsewhere is named outright by one of the clause's words ("buckets",
    an alias of the range's ball dispenser): that alternative's room."""
    if prep not in lx.DESTINATION_PREPOSITIONS or match.kind != "zone" or left_zone(s, history, at) != match.name:
        return None
    words = [lemma(w) for w in said]
    for name in alternatives:
        entry = index.entry(name)
        if entry is None or entry.zone == match.name or not any(_says(words, phrase) for phrase in entry.phrases):
            continue
        room = index.entry(entry.zone) if entry.kind == "entity" else None
        chosen = room if room is not None else entry
        why = f"{reason}; not {match.name}, where they set off from, but {name}, said by name: {chosen.name}"
        return PlaceMatch(chosen.name, chosen.kind, chosen.zone, match.score, False), (match.name,), why
    return None


def _says(words: Sequence[str], phrase: Sequence[str]) -> bool:
    """Whether `phrase` (an alias, lemmatised) stands whole among `words`."""
    n = len(phrase)
    return n > 0 and any(tuple(words[i:i + n]) == tuple(phrase) for i in range(len(words) - n + 1))
