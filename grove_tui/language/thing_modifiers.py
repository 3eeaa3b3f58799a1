"""A person noun used as a modifier of a thing: "their patient files are in the office", "the visitor
badges lie on the desk". The small parser tags such a word an adjective or a compound, and an "-s"
noun after a singular person could be that person's verb ("the patient files into the room"), so
the lexicon cannot tell; the word after the pair can: a finite verb there ("are", "lie") makes the
"-s" word the subject's noun and the person word only what kind of thing it is."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import verb_lemma

_FINITE_TAGS = frozenset({"VBP", "VBZ", "VBD", "MD"})
# Words the small parser tags a finite verb after an "-s" verb it took for a noun ("a visitor swerves
# round the robot"): a particle or preposition, so the "-s" word was the verb.
_NOT_VERBS = frozenset("and or round around about past by off up down over back away along".split())


def modifies_a_thing(s: Sentence, k: int, *, person_next: bool) -> bool:
    """Whether the singular person word at k names only the kind of the plural noun after it, the
    subject of the finite verb after that noun. `person_next` says whether that noun is a person
    ("the patient visitors are ...": people, whoever they visit)."""
    if k + 2 >= s.n or person_next or s.lemma(k) != s.low[k]:
        return False
    word, noun, verb = s.w[k], s.w[k + 1], s.w[k + 2]
    if word.dep not in ("compound", "amod") or word.head != k + 1:
        return False  # "a cleaner wanders round ...": the parser's subject, then its verb
    if (verb_lemma(s.low[k + 1]) in lx.INTENT_VERBS or verb_lemma(s.low[k + 1]) in lx.HUMAN_SUBJECT_VERBS) and verb.pos != "AUX":
        return False  # "a cleaner wanders round the kitchen": a verb people do, then a word the parser calls one
    return noun.tag == "NNS" and (verb.tag in _FINITE_TAGS or verb.pos == "AUX") and \
        s.low[k + 2] not in _NOT_VERBS and s.low[k + 2] not in lx.PLACE_PREPOSITIONS
