"""A treatment someone is on is no place (round 53): "six patients on dialysis hang about by the
transport board", "a man on oxygen sits in the waiting room", "two lads on crutches". After a person's
noun, "on" and a bare noun of a treatment, a drug or a support (no determiner: "on the dialysis ward"
is a place) says what the person is having, though a room of the world may share the word."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import lemma

# Nouns of what a person is on: a treatment, a drug, a support.
TREATMENTS = frozenset("""dialysis haemodialysis hemodialysis chemo chemotherapy radiotherapy oxygen
    ventilator ventilation antibiotics antibiotic steroids steroid medication medicine meds insulin methadone
    morphine painkillers drip drips fluids crutches sticks warfarin treatment therapy physio
    probation parole benefits furlough placement""".split())


def on_treatment(s: Sentence, k: int, prep: str, at: int) -> bool:
    """Whether "on" at `at` and the bare noun at k name a treatment a person is on (module doc)."""
    if prep != "on" or at < 1 or k >= s.n or s.low[at] != "on" or s.low[k] in lx.DETERMINERS:
        return False
    end = k
    while end + 1 < s.n and s.low[end + 1] in TREATMENTS:
        end += 1  # "on home haemodialysis": the last word says it
    if s.low[end] not in TREATMENTS and lemma(s.low[end]) not in TREATMENTS:
        return False
    if end + 1 < s.n and s.low[end + 1].isalpha() and s.index.knows(lemma(s.low[end + 1])):
        return False  # "on dialysis bay 2": a place's own name
    before = s.lemma(at - 1)
    return before in lx.PERSON_NOUNS or s.low[at - 1] in lx.PERSON_NOUNS or s.w[at - 1].pos in ("NOUN", "PROPN", "PRON")
