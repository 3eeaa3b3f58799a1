"""Where a group comes from, said by a name after "from" (round 33): "A coachload of day-trippers from
Wales mills around the atrium", "a party of schoolkids from St Mary's troops in". The parser's fixes
read the name before the "-s" verb as its subject ("Wales mills", as "Ines sketches"), and the name was
a person of its own, the group before it a second group that did nothing. A name right after "from"
that ends a phrase about people is where they come from: the phrase's first noun is the verb's subject."""

from __future__ import annotations

from dataclasses import replace

from grove_tui.language.parser import Word


def _top_noun(words: list[Word], k: int) -> int:
    """The noun a chain of "of" and "from" phrases hangs from ("coachload" in "a coachload of day-trippers")."""
    seen = 0
    while seen < 8:
        seen += 1
        prep = words[k].head
        if words[k].dep != "pobj" or prep == k or words[prep].pos != "ADP" or words[prep].head == prep:
            return k
        k = words[prep].head
    return k


def origins_not_subjects(words: list[Word]) -> list[Word]:
    """The parse with a name after "from", made a verb's subject, read as where the people before it
    come from (module doc)."""
    out = list(words)
    for i, w in enumerate(words):
        if w.dep != "nsubj" or w.pos != "PROPN" or w.head <= i or i < 3:
            continue
        start = i
        while start > 0 and words[start - 1].pos == "PROPN" and words[start - 1].sentence == w.sentence:
            start -= 1  # "from St Mary's"
        prep = start - 1
        if prep < 2 or words[prep].lower != "from" or words[prep - 1].pos != "NOUN" or \
                words[prep - 1].tag not in ("NNS", "NN"):
            continue
        if any(x.pos in ("VERB", "AUX") for x in words[:prep] if x.sentence == w.sentence):
            continue  # "she walks from Wales ...": a verb's place, not a phrase's
        owner = prep - 1
        subject = _top_noun(out, owner)
        verb = w.head
        out[prep] = replace(out[prep], dep="prep", head=owner)
        out[i] = replace(out[i], dep="pobj", head=prep)
        out[subject] = replace(out[subject], dep="nsubj", head=verb)
    return out
