"""Words that put what follows later (round 21): "then", "afterwards", "later", and "before" with a
verb in -ing after it ("walk to the cafeteria before going to the pharmacy"). A place gone to after
such a word is the next stop: the one gone to before it is passed on the way."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.sentence import Sentence


def later_words(s: Sentence, first: int, end: int) -> list[int]:
    """Where, in [first, end), a word says that what follows comes later."""
    return [i for i in range(first, end) if s.low[i] in lx.SEQUENCE_WORDS or (
        s.low[i] == "before" and i + 1 < s.n and s.w[i + 1].tag == "VBG")]


def goes_on_after(later: list[int], before_index: int, index: int) -> bool:
    """Whether a word of `later` stands between a place said at `before_index` and one at `index`."""
    return any(before_index < t < index for t in later)
