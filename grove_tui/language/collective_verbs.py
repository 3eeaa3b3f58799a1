"""A verb the parser takes for a noun after a collective (round 56): "While two volunteers restock the
shelf, a pair solder at the bench and a dozen newcomers sit in the classroom", "a couple queue at the
till and three kids sit ...". The parser makes the collective a modifier of the verb ("pair solder")
and the verb a second subject of the sentence's later verb, so a "solder" was one person beside the
pair. A singular noun right after a collective that modifies it, followed by a preposition, that the
parser makes a subject of a verb which has another subject after it, is the collective's verb."""

from __future__ import annotations

from dataclasses import replace

from grove_tui.language import lexicon as lx
from grove_tui.language.parser import Word


def as_collective_verbs(words: list[Word]) -> list[Word]:
    """The parse with a collective's verb, taken for a noun it modifies, tagged a verb (module doc)."""
    out = list(words)
    for k, w in enumerate(words):
        if k == 0 or k + 1 >= len(words) or w.pos != "NOUN" or w.tag != "NN" or w.dep != "nsubj":
            continue
        prev, nxt = words[k - 1], words[k + 1]
        if prev.lower not in lx.IMPLIED_RANGES or prev.dep != "compound" or prev.head != k or \
                nxt.pos != "ADP" or nxt.sentence != w.sentence:
            continue
        if w.lower in lx.IMPLIED_RANGES or w.lower in lx.PERSON_NOUNS or w.lower in lx.NON_PEOPLE:
            continue  # "a tour guide", "a group photo": a noun of its own
        if not any(x.dep == "nsubj" and x.head == w.head and j > k and x.sentence == w.sentence
                   for j, x in enumerate(words)):
            continue  # the parser's tree has one subject for the verb: leave it
        out[k] = replace(w, pos="VERB", tag="VBP", lemma=w.lower, dep="conj", head=w.head)
        out[k - 1] = replace(prev, dep="nsubj", head=k)
    return out
