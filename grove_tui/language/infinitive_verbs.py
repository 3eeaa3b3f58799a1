"""A verb after the "to" of a purpose is no place (issue 29): "wanders round to goods in to sign for a
pallet", "hurries to reception to collect her badge". The parser tags the infinitive "to" TO and the bare
verb after it VB, while the "to" of a place is a preposition (IN); a word the parser reads so is what
they go to do, never a place of the world to read, nor an unknown one to refuse. A word that is a
place's whole name ("to board" a "board"?) is left to the place reader."""

from __future__ import annotations

from grove_tui.language.sentence import Sentence


def infinitive_verb(s: Sentence, k: int, at: int) -> bool:
    """Whether the bare word at k, right after a "to" (the preposition at `at` or its last word), is the verb of an infinitive."""
    if not (0 <= at < k < s.n) or s.low[k - 1] != "to":  # "in to sign": "to" ends the preposition at `at`
        return False
    return s.w[k - 1].tag == "TO" and s.w[k].tag == "VB"
