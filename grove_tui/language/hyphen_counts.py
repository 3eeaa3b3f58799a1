"""A count before a hyphenated describing phrase and a person noun the lexicon lacks: "twenty
season-ticket holders" was read, and "a pair of art-college sketchers", "a trio of art-school
doodlers", "a couple of first-year sketchers" were lost (the phrase read as no one's, the count with
it), as the count was looked for only as a number right before the hyphenated words."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.sentence import Sentence


def count_ends_at(s: Sentence, i: int) -> bool:
    """Whether word i ends a count said before a phrase: a number ("twenty"), or the "of" of a
    collective counting people ("a pair of", "a group of", "a couple of")."""
    if i < 0:
        return False
    if s.w[i].pos == "NUM":
        return True
    before = s.lemma(i - 1) if i > 0 else ""
    return s.low[i] == "of" and (before in lx.TOGETHER_COLLECTIVES or before in lx.IMPLIED_RANGES)
