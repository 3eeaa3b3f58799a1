"""Verbs of pushing a thing along that the small parser takes for a noun between people in the plural
and the thing (round 31): "a couple of young mums wheel prams from the atrium into the toy shop", read
as "mums wheel prams", one noun, so the mums are lost from the list of groups. A pushing word made a
noun, right after a plural noun of people and right before a noun phrase (the thing: "prams", "their
cases", "a bed") that a preposition, a comma, "and" or the end follows, is the people's verb; the
plural is its subject and the thing its object."""

from __future__ import annotations

from dataclasses import replace

from grove_tui.language import lexicon as lx
from grove_tui.language.parser import Word

_PUSHING = frozenset("wheel push pull drag steer trundle roll tow haul lug shove cart".split())
_FORMS = {f"{v}{end}": v for v in _PUSHING for end in ("", "s", "es")}
_THING_WORDS = frozenset({"DET", "ADJ", "NOUN", "PRON", "NUM"})
_AFTER = frozenset({"ADP", "PUNCT", "CCONJ", "ADV", "SCONJ", "PART"})


def _person_plural(w: Word) -> bool:
    if w.tag not in ("NNS", "NNPS"):
        return False
    low = w.lemma.lower() if w.lemma else w.lower
    return low in lx.PERSON_NOUNS or low in lx.KIN_NAMES or w.lower.rstrip("s") in lx.KIN_NAMES or \
        w.lower[:-1] in lx.PERSON_NOUNS


def _person_singular(w: Word) -> bool:
    """A person said as one, whatever the parser took the word for ("auxiliary": an adjective)."""
    return w.tag in ("NN", "NNP", "JJ") and (w.lower in lx.PERSON_NOUNS or w.lower in lx.KIN_NAMES)


def _thing_end(words: list[Word], k: int) -> int | None:
    """The last word of the thing pushed after word k, or None when no noun phrase follows."""
    j, end = k + 1, None
    while j < len(words) and words[j].sentence == words[k].sentence and words[j].pos in _THING_WORDS:
        if words[j].pos == "NOUN":
            end = j
        elif end is not None:
            break
        j += 1
    if end is None or (end + 1 < len(words) and words[end + 1].sentence == words[k].sentence and
                       words[end + 1].pos not in _AFTER):
        return None
    return end


def as_pushing_verbs(words: list[Word]) -> list[Word]:
    """The parse with a pushing verb taken for a noun after people tagged their verb (module doc)."""
    out = list(words)
    for k, w in enumerate(words):
        if k == 0 or w.pos != "NOUN" or w.lower not in _FORMS:
            continue
        one = w.lower != _FORMS[w.lower] and _person_singular(out[k - 1])  # "a nursing auxiliary wheels linen"
        if not (one or _person_plural(out[k - 1])):
            continue
        end = _thing_end(out, k)
        if end is None:
            continue
        thing = out[end]
        root = next((x.i for x in out if x.sentence == w.sentence and x.dep == "ROOT"), end)
        if thing.dep == "ROOT" or root == end:
            dep, head = "ROOT", k
        else:
            dep, head = "conj", root
        out[k] = replace(w, pos="VERB", tag="VBZ" if one else "VBP", lemma=_FORMS[w.lower], dep=dep, head=head)
        for j, x in enumerate(out):
            if j == k:
                continue
            if x.head in (k, end) and j < k - 1:
                out[j] = replace(x, head=k - 1)  # "two young mums": the count is the people's
            elif x.head in (k, end) and j > end:
                out[j] = replace(x, head=k)  # "from the atrium": the verb's
        out[k - 1] = replace(out[k - 1], dep="nsubj", head=k)
        out[end] = replace(out[end], dep="dobj", head=k)
        if dep == "ROOT":
            for j, x in enumerate(out):
                if x.sentence == w.sentence and x.dep == "ROOT" and j != k:
                    out[j] = replace(x, dep="conj", head=k)
    return out
