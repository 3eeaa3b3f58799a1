"""A verb and its particle after "to", which the parser takes for a noun: "queue at the counter to hand in
their coats", "stop by reception to drop off the keys", "wait at the desk to fill in a form". A word the
world does not call a place, then "in"/"off"/"up"/... and a determiner, is a verb of a purpose, not a
place to go to."""

from __future__ import annotations

from collections.abc import Callable, Sequence

from grove_tui.language import lexicon as lx
from grove_tui.language.tokens import lemma

VERB_PARTICLES = frozenset("in off out up back down over away on".split())


def particle_verb(low: Sequence[str], k: int, knows: Callable[[str], bool]) -> bool:
    """Whether the word at k, after "to", is a verb with its particle ("hand in their coats")."""
    if k + 2 >= len(low) or low[k + 1] not in VERB_PARTICLES or low[k + 2] not in lx.DETERMINERS:
        return False
    w = low[k]
    if not w.isalpha() or knows(lemma(w)) or w in lx.PERSON_NOUNS or lemma(w) in lx.PERSON_NOUNS:
        return False  # "to the lobby in ...", "talk to friends in the bar": a place or a person
    return not (w.endswith("s") and not w.endswith("ss"))  # a plural is a thing, a base verb ends otherwise
