"""A plural verb of going in its base form after a place phrase (round 63): "the eight kids on the Saturday
lesson head for the outdoor manège", "the lads on the stag do head off to the bar". "head" there is the
subject's verb, not the last word of a place's name: a base-form verb of going the world does not know as a
word, right before where-to ("for", "to", "towards", "off", "back", "home"), ends the phrase. Kept narrow:
a word the world knows ("from the toy shop to the bookshop", "the pier head") stays in the name, and so does
a phrase that already names a place whole."""

from __future__ import annotations

from collections.abc import Callable, Sequence

from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import lemma, verb_lemma

# Verbs of setting off that are nouns too, so the tagger reads them as a name's last word.
_HEADING = frozenset("head".split())
_WHERE_TO = frozenset("for to towards toward off back home over across straight".split())


def heading_before_where_to(s: Sentence, j: int) -> bool:
    """Whether the word at j is a base-form verb of heading off, unknown to the world, before where-to."""
    w = s.low[j]
    return (w in _HEADING and verb_lemma(w) == w and j + 1 < s.n and s.low[j + 1] in _WHERE_TO
            and not s.index.knows(lemma(w)) and not s.index.knows(w))


def heading_verb_after(s: Sentence, phrase: Sequence[str], j: int,
                       whole_name: Callable[[Sequence[str]], bool]) -> bool:
    """Whether the word at j is the subject's verb of going, not part of the place phrase (module doc)."""
    return bool(phrase) and heading_before_where_to(s, j) and not whole_name(phrase) \
        and not whole_name([*phrase, s.low[j]])
