"""A role, then the person's name, then their verb (round 51): "our guide Priya strolls ...", "my
colleague Sam walks ...". The parser makes the name an apposition of the role and the role the
subject; the name then named nobody and the person was lost. A capitalised name right after a
singular person noun said with a possessive or "the", and before a verb, is that one person."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import verb_lemma

_OWNERS = frozenset({"our", "my", "his", "her", "their", "your", "the"})


def apposed_name(s: Sentence, i: int) -> bool:
    """Whether word i is a name said after the role it is ("our guide Priya walks"): module doc."""
    if i < 2 or i + 1 >= s.n or s.w[i].pos != "PROPN" or not s.w[i].text[:1].isupper() or \
            not s.w[i].text[1:].islower() or s.low[i - 2] not in _OWNERS:
        return False
    role = s.w[i - 1]
    if role.pos != "NOUN" or role.tag != "NN" or s.lemma(i - 1) not in lx.PERSON_NOUNS or s.index.knows(s.low[i]):
        return False
    after = s.w[i + 1]
    return after.sentence == s.w[i].sentence and (after.tag in ("VBZ", "VBD") or (
        after.tag == "NNS" and verb_lemma(s.low[i + 1]) in lx.INTENT_VERBS))
