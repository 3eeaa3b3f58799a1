"""People called by an animal idiom (round 39): "about 35 early birds stream through the doors", "a
couple of gym rats wait by the lockers", "three party animals stagger out of the bar". An animal alone
is no person ("two pigeons by the fountain"), so the reader read nobody and guessed a vague crowd; an
animal right after the word that makes it an idiom for people is a person, counted like one."""

from __future__ import annotations

from grove_tui.language.sentence import Sentence

# animal lemma -> the words before it that make it a person
_IDIOMS: dict[str, frozenset[str]] = {
    "bird": frozenset("early night rare".split()),
    "animal": frozenset("party social political".split()),
    "rat": frozenset("gym mall rug".split()),
    "duck": frozenset("lame sitting odd".split()),
    "horse": frozenset("dark".split()),
    "bee": frozenset("busy worker queen spelling".split()),
    "cat": frozenset("cool fat scaredy copy".split()),
    "dog": frozenset("top".split()),
    "fish": frozenset("cold odd".split()),
    "fox": frozenset("silver".split()),
}


def animal_idiom_person(s: Sentence, i: int) -> bool:
    """Whether word i is an animal said as people by the word before it ("early birds", "gym rats")."""
    words = _IDIOMS.get(s.lemma(i))
    if words is None or i < 1 or s.low[i - 1] not in words:
        return False
    return s.w[i].pos in ("NOUN", "PROPN")
