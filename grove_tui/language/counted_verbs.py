"""A verb of going right after a bare number that the small parser takes for a noun counted by it
(round 37): "Of the 12 members in the event space, 4 duck into the phone booths", "twenty shoppers
sit in the food court; five dart into the cinema", "three hop over to the bar", and after a word of
a count ("half a dozen peel off to the toy store", "a handful duck into the booths"). Read so, "4 duck"
is four ducks and the part moving off is lost. A singular noun is not counted by a number above
one, so such a word, a verb of going, right after a number and before a word of direction, is the
number's verb, and the number its subject ("four of them")."""

from __future__ import annotations

from dataclasses import replace

from grove_tui.language import lexicon as lx
from grove_tui.language.parser import Word

# verbs of going that are nouns too, beyond those the lexicon gives an intent
_GOING = frozenset("duck dart hop crowd limp scurry scuttle creep crawl dash bolt race file troop pop nip slip "
                   "step jog trot stroll wander head amble march stride rush hurry shuffle drift sneak scoot "
                   "skip run walk stream pile spill squeeze edge peel break split branch slope slink sidle veer "
                   "splinter".split())
# words of a count that the parser leaves a noun or adjective ("half a dozen peel off", "a handful duck into")
_COUNT_WORDS = frozenset("dozen score handful couple pair few several".split())
_DIRECTIONS = frozenset("into in out off over back across through to towards toward up down along past round "
                        "around away inside outside onto on under behind".split())


def _going(low: str) -> bool:
    return low.isalpha() and (low in _GOING or lx.INTENT_VERBS.get(low) == "walk")


def as_counted_verbs(words: list[Word]) -> list[Word]:
    """The parse with a verb of going, taken for a noun a bare number counts, tagged the number's verb
    (module doc)."""
    out = list(words)
    for k in range(1, len(out) - 1):
        w, num, nxt = out[k], out[k - 1], out[k + 1]
        if w.pos != "NOUN" or w.tag != "NN" or not _going(w.lower) or num.head != k:
            continue
        if num.pos != "NUM" and not (num.lower in _COUNT_WORDS and num.dep in ("nummod", "compound", "amod")):
            continue
        if num.lower in ("one", "1") or nxt.lower not in _DIRECTIONS or nxt.sentence != w.sentence:
            continue
        if k >= 2 and out[k - 2].pos in ("NOUN", "PROPN", "ADJ") and out[k - 2].sentence == w.sentence:
            continue  # "room 4 hop", a number naming a thing
        root = next((j for j, x in enumerate(out) if x.sentence == w.sentence and x.dep == "ROOT"), k)
        out[k] = replace(w, pos="VERB", tag="VBP", lemma=w.lower, dep="ROOT", head=k)
        out[k - 1] = replace(num, dep="nsubj", head=k)
        if root != k:
            old = out[root]
            dep = "ccomp" if old.pos in ("VERB", "AUX") else ("prep" if old.pos == "ADP" else "dep")
            out[root] = replace(old, dep=dep, head=k)
    return out
