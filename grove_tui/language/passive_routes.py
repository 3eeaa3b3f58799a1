"""The "by" of a passive of taking that the parser hangs on a word of the route (round 27): "Mrs
Okoro is wheeled up to ward B by a porter", where "to ward" reads as a verb and "by a porter" as
its phrase. The first "by" after the verb, in its clause, that ends the clause with a person said
with an article or a count, is the passive's "by"."""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language.parser import Word

_OPENERS = frozenset("a an the two three four five six his her their our".split())
_CLAUSE_ENDS = frozenset({",", ".", ";", "!", "?", "and", "while", "as", "then", "but"})


def late_by(words: Sequence[Word], verb: Word) -> Word | None:
    """The "by" of the passive verb `verb` the parser did not hang on it (see the module doc)."""
    for w in words[verb.i + 1:]:
        if w.sentence != verb.sentence or w.lower in _CLAUSE_ENDS:
            return None
        if w.lower == "by" and w.i + 2 < len(words) and words[w.i + 1].lower in _OPENERS:
            end = next((x.i for x in words[w.i + 1:] if x.lower in _CLAUSE_ENDS or x.sentence != w.sentence),
                       len(words))
            nouns = [x for x in words[w.i + 1:end] if x.pos in ("NOUN", "PROPN")]
            return w if nouns and end - w.i <= 5 else None
    return None
