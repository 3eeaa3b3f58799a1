"""A passive of taking someone somewhere whose "by" phrase the parser hangs on the route (round 37): "Mrs
Okoro is wheeled up to ward B by a porter", "the twins are taken to dock 2 by their dad". A place word
after "to" that the parser takes for a verb ("to ward B") leaves the "by" phrase no agent of the
passive, and the taker is lost. When the passive's own verb is one of taking, the route follows it at
once, and the "by" phrase after the route names a person (a person word, a title or a name), the clause
is said again in the active as `passive_escort` does: "a porter wheels Mrs Okoro up to ward B".
"""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language import lexicon as lx
from grove_tui.language.parser import Word
from grove_tui.language.passive_escort import _ROUTE_WORDS, _span
from grove_tui.language.tokens import third_person

_TAKING = lx.LEADING_VERBS | frozenset({"march", "frogmarch", "bundle", "hustle", "stretcher"})
_COUNTED = frozenset("two three four five six seven eight nine ten some".split())
_OPENERS = frozenset("a an the his her their our my your two three four five six seven eight nine ten some".split())


def _taker(words: Sequence[Word], by: int) -> tuple[int, int] | None:
    """The first and last word of the person named after "by" at `by`, or None when no person is named
    there ("by the lifts", "by bus")."""
    k = by + 1
    while k < len(words) and (words[k].lower in _OPENERS or words[k].pos == "ADJ") and words[k].lower != "by":
        k += 1
    if k >= len(words):
        return None
    first, last = by + 1, k
    while last + 1 < len(words) and words[last + 1].pos == "PROPN" and words[last + 1].text[:1].isupper():
        last += 1  # "by Nurse Jo Platt"
    head = words[last]
    said = {words[j].lower for j in range(k, last + 1)} | {words[j].lemma for j in range(k, last + 1)}
    person = bool(said & (lx.PERSON_NOUNS | set(lx.TITLES))) or (
        head.pos == "PROPN" and head.text[:1].isupper() and first == k)
    if not person or said & lx.PERSON_THINGS:
        return None
    return first, last


def late_agents_to_active(text: str, words: Sequence[Word]) -> str | None:
    """The text with each passive of taking whose "by" phrase the parser hung on the route said in the
    active (see the module doc); None when there is none."""
    out = text
    for verb in sorted((w for w in words if w.tag == "VBN" and w.lemma in _TAKING), key=lambda w: -w.i):
        kids = [w for w in words if w.head == verb.i and w.i != verb.i]
        subject = next((w for w in kids if w.dep == "nsubjpass"), None)
        if subject is None or any(w.dep == "agent" for w in kids) or verb.i + 1 >= len(words) or \
                words[verb.i + 1].lower not in _ROUTE_WORDS:
            continue
        by = next((w.i for w in words[verb.i + 2:] if w.lower == "by" or w.sentence != verb.sentence
                   or w.pos == "PUNCT" or w.lower in ("and", "while", "as", "then")), None)
        if by is None or words[by].lower != "by":
            continue
        taker = _taker(words, by)
        if taker is None:
            continue
        taker_first, taker_last = taker
        first, last = _span(words, subject.i)
        between = words[last + 1:verb.i]
        if not between or any(w.dep not in ("auxpass", "aux", "advmod", "neg") for w in between) or last >= verb.i:
            continue
        # "Mrs Okoro, fresh from her scan, is wheeled ...": the aside is no part of whom the taker takes
        last = next((j - 1 for j in range(subject.i + 1, last + 1) if words[j].lower == ","), last)
        plural = words[taker_last].tag in ("NNS", "NNPS") or words[taker_first].lower in _COUNTED
        active = verb.lemma if plural else third_person(verb.lemma)
        taker_text = text[words[taker_first].start:words[taker_last].end]
        taken_text = text[words[first].start:words[last].end].rstrip(" ,")
        route = text[verb.end:words[by].start].rstrip()
        if first == 0:
            taker_text = taker_text[:1].upper() + taker_text[1:]
            taken_text = taken_text[:1].lower() + taken_text[1:] if words[first].pos == "DET" else taken_text
        out = out[:words[first].start] + f"{taker_text} {active} {taken_text}{route}" + out[words[taker_last].end:]
    return None if out == text else out
