"""The shop's till as a word before a noun (round 47): "a pair of till staff gossip", "the till
queue", "two till operators". The small parser tags "till" as the conjunction ("wait till the coach
comes") wherever it stands, so the people after it are lost and the count falls back to a guess.
After a determiner, a count or "of", and before a noun, "till" is a noun that names a kind (a
compound), never a word of time; "wait till the doors open" is left alone (no determiner before)."""

from __future__ import annotations

from dataclasses import replace

from grove_tui.language.parser import Word

_TILL = frozenset({"till", "tills"})
_BEFORE = frozenset({"a", "an", "the", "of", "their", "our", "his", "her", "its", "two", "three", "four",
                     "five", "six", "seven", "eight", "nine", "ten", "some", "few", "several", "both", "main"})


def _noun_after(words: list[Word], k: int) -> bool:
    if k + 1 >= len(words):
        return False
    nxt = words[k + 1]
    return nxt.pos in ("NOUN", "PROPN") and nxt.lower not in ("the", "a", "an")


def with_till_nouns(words: list[Word]) -> list[Word]:
    """The parse with a "till" before a noun, after a determiner, count or "of", tagged as a noun."""
    out = list(words)
    for k, w in enumerate(words):
        if w.lower not in _TILL or w.pos in ("NOUN", "PROPN") or k == 0:
            continue
        prev = words[k - 1]
        if (prev.lower in _BEFORE or prev.pos == "NUM") and _noun_after(words, k):
            out[k] = replace(w, pos="NOUN", tag="NN", lemma="till", dep="compound", head=k + 1)
    return out
