"""A second verb of one person the small parser takes for a plural noun after "and": "a new temp is
frightened of the robot and cowers whenever it passes", "a toddler stares at it and hides behind his
mum". Read as a noun, "cowers" is a second group of people; read by its place (after "and", a verb
before it, one person its subject, a verb the lexicon knows, a word of time, place or manner after it)
it is the person's second verb."""

from __future__ import annotations

from dataclasses import replace

from grove_tui.language import lexicon as lx
from grove_tui.language.parser import Word
from grove_tui.language.tokens import verb_lemma

_AFTER = frozenset({"ADP", "ADV", "SCONJ", "PART"})


def as_second_verbs(words: list[Word]) -> list[Word]:
    """The parse with the second verb of one person, taken for a plural noun, tagged a verb."""
    out = list(words)
    for k in range(2, len(words) - 1):
        w, nxt = words[k], words[k + 1]
        if w.tag != "NNS" or words[k - 1].lower != "and" or nxt.sentence != w.sentence or nxt.pos not in _AFTER:
            continue
        base = verb_lemma(w.lower)
        if base == w.lower or not (base in lx.ROBOT_VERBS or base in lx.INTENT_VERBS):
            continue
        before = [j for j in range(k - 1) if words[j].sentence == w.sentence]
        verbs = [j for j in before if words[j].pos in ("VERB", "AUX")]
        subjects = [j for j in before if words[j].dep == "nsubj"]
        if not verbs or not subjects or words[subjects[0]].tag not in ("NN", "NNP"):
            continue  # one person only: "two nurses check charts and files" is no verb
        out[k] = replace(w, pos="VERB", tag="VBZ", lemma=base, dep="conj", head=verbs[0])
    return out
