"""Misspelt words of a count said with "of" ("a coupel of guards", "a cuple of porters", "a handfull of
kids", "a coupla nurses", "a familly of four"), put right before the prompt is parsed. The reader knew no such word, took
"a coupel" for one person, and the group counted one where the sentence says two. Only after "a"
and before "of" (the words' own frame), only a word one edit from the count's word, and never a real
English word ("a pail of water" stays)."""

from __future__ import annotations

import re

from grove_tui.language.parser import known_word

# The count words said as "a ... of": the reader reads each once spelt right.
_COUNT_WORDS = ("couple", "handful", "dozen", "pair", "group", "bunch", "crowd", "gaggle", "trio", "team",
                # collectives whose "of" gives their size ("a familly of four", "a partty of six")
                "family", "party", "squad", "horde", "throng", "army")
_OF_FRAME = re.compile(r"\b([Aa])\s+([a-z]{3,9})\s+of\b")
# Chat's run-together "couple of" ("a coupla nurses", "a cuppla guards").
_COUPLA = re.compile(r"\b([Aa])\s+(?:coupla|cupla|cuppla|couplea|coupl)\b(?!\s+of\b)")


def _spelt(m: re.Match[str]) -> str:
    from grove_tui.language.spelling import one_edit  # spelling imports text, which runs this

    word = m.group(2)
    if word in _COUNT_WORDS or known_word(word):
        return m.group(0)
    right = next((c for c in _COUNT_WORDS if len(c) >= 4 and one_edit(word, c)), None)
    return m.group(0) if right is None else f"{m.group(1)} {right} of"


def count_words_spelt(text: str) -> str:
    """The text with a misspelt count word before "of" written right (module doc)."""
    return _OF_FRAME.sub(_spelt, _COUPLA.sub(lambda m: f"{m.group(1)} couple of", text))
