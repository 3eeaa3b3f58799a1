"""A verb after the "to" of a purpose is no place (issue 29): "wanders round to goods in to sign for a
pallet", "hurries to reception to collect her badge". The parser tags the infinitive "to" TO and the bare
verb after it VB, while the "to" of a place is a preposition (IN); a word the parser reads so is what
they go to do, never a place of the world to read, nor an unknown one to refuse. A word that is a
word with a place's number after it or nothing at all ("to gate C4", "to gate.", where the parser reads
"gate" as a verb) is left to the place reader."""

from __future__ import annotations

from grove_tui.language.sentence import IDENTIFIER, Sentence


def infinitive_verb(s: Sentence, k: int, at: int) -> bool:
    """Whether the bare word at k, right after a "to" (the preposition at `at` or its last word), is the verb of an infinitive."""
    if not (0 <= at < k < s.n) or s.low[k - 1] != "to":  # "in to sign": "to" ends the preposition at `at`
        return False
    if k + 1 >= s.n or s.is_punct(k + 1) or any(IDENTIFIER.fullmatch(w) and not w.isalpha() for w in s.low[k + 1:k + 4]):
        return False  # "walk to gate C4", "to gate.": the parser's verb is a place's word, its number or nothing after
    return s.w[k - 1].tag == "TO" and s.w[k].tag == "VB"
