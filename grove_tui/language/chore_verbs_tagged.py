"""A chore verb in "-s" the parser took for a noun between its doer and its object (round 60): "A
keeper preps fish in the yard, ...", "a porter sluices trays by the sink". The small parser reads
"keeper preps fish" as one noun compound, so the clause had no verb and its person was lost (in a list
of clauses, only the later ones were read). After a noun opened by "a", "an", "the" or a number, a
word in "-s" whose stem is a chore verb (language/chore_subjects.py), followed by a noun or a
determiner, is retagged as the verb, the noun before it its subject and the noun after it its object."""

from __future__ import annotations

from dataclasses import replace

from grove_tui.language.chore_subjects import CHORE_VERBS
from grove_tui.language.parser import Word

_OPENERS = frozenset("a an the two three four five six seven eight nine ten our their his her".split())
_OBJECT_OPENERS = frozenset("a an the some his her their its".split())
# What stays the object's own: its determiner and modifiers.
_NOUN_DEPS = frozenset("det amod compound nummod poss case".split())


def _chore_form(low: str) -> bool:
    if not low.endswith("s") or len(low) < 4:
        return False
    stems = {low[:-1], low[:-2] if low.endswith("es") else "", low[:-3] + "y" if low.endswith("ies") else ""}
    return bool(stems & CHORE_VERBS)


def as_chore_verbs(words: list[Word]) -> list[Word]:
    """The parse with a chore verb taken for a noun in "a keeper preps fish" tagged as the verb (module doc)."""
    out = list(words)
    for k in range(2, len(words) - 1):
        w, doer, after = words[k], words[k - 1], words[k + 1]
        if w.pos != "NOUN" or not _chore_form(w.lower) or doer.pos != "NOUN" or doer.dep != "compound":
            continue
        if words[k - 2].lower not in _OPENERS:
            continue
        if not (after.pos == "NOUN" or after.lower in _OBJECT_OPENERS):
            continue
        obj = after.head if after.lower in _OBJECT_OPENERS else k + 1
        if obj <= k or obj >= len(words) or words[obj].pos != "NOUN":
            continue
        root = words[obj]
        out[k] = replace(w, pos="VERB", tag="VBZ", lemma=w.lower[:-1] if w.lower[:-1] in CHORE_VERBS else w.lemma,
                         dep=root.dep, head=k if root.head == obj else root.head)
        out[k - 1] = replace(doer, dep="nsubj", head=k)
        out[obj] = replace(out[obj], dep="dobj", head=k)
        for j, x in enumerate(words):
            if j not in (k - 1, k, obj) and x.head == obj and x.dep not in _NOUN_DEPS:
                out[j] = replace(out[j], head=k)  # "in the yard", a later clause: the verb's, not the object's
    return out
