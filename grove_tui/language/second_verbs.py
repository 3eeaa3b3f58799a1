"""A word in a verb's place after "and" or "then" that looks like a misspelt person noun: the second
verb of the clause's subject ("a toddler waves at the robot and toddles after it": "toddles" is one
letter from "toddlers", but it is what the toddler does next, not another group)."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.sentence import Sentence

_JOINS = frozenset({"and", "then", "or"})
# What follows a verb and never a subject's noun: a preposition, determiner, pronoun, adverb or the end.
_AFTER_A_VERB = frozenset({"ADP", "DET", "PRON", "ADV", "PUNCT", "PART"})


def second_verb(s: Sentence, i: int) -> bool:
    """Whether word i, an "-s" word right after "and"/"then" (no determiner or number of its own),
    followed by what only follows a verb, is the verb of the subject said before: a subject's noun
    after "and" is followed by its own verb ("... and passangers wait")."""
    if i < 1 or s.low[i - 1] not in _JOINS or not s.low[i].endswith("s") or s.low[i].endswith("ss"):
        return False
    if i + 1 < s.n and (s.w[i + 1].pos not in _AFTER_A_VERB and s.low[i + 1] not in lx.DETERMINERS):
        return False
    # the clause before has its own subject and verb: "and" joins two predicates, not two subjects
    return any(s.w[k].pos in ("NOUN", "PROPN", "PRON") for k in range(i - 1) if s.w[k].sentence == s.w[i].sentence)
