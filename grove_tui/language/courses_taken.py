"""A course people are on is no place (round 50): "a lad on the knife-skills course", "trainees on an
induction programme", "a nurse on the first-aid course", "kids on the Saturday lesson" (round 63). After "on", such a head names what they are
doing, like an outing (outing_words.py), so a world without one refuses nothing; a world that calls a
place by the head ("the course" of a racecourse) keeps it a place."""

from __future__ import annotations

from grove_tui.language.heading_verbs import heading_before_where_to
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import lemma
from grove_tui.language.verb_after_place import verb_before_particle

_COURSE_HEADS = frozenset("course class workshop programme program scheme placement apprenticeship induction "
                          "module masterclass bootcamp residency internship lesson".split())


def a_course_taken(s: Sentence, k: int, prep: str) -> bool:
    """Whether the phrase from k after `prep` is a course people are on (module doc)."""
    if prep != "on":
        return False
    j = k
    while j < min(s.n, k + 7) and (s.w[j].pos in ("DET", "ADJ", "NOUN", "PROPN", "NUM") or s.hyphen_inside(j) or
                                   (j > k and s.hyphen_inside(j - 1)) or s.w[j].tag == "VBG"):
        # "the knife-skills course", "a coaching course"
        head = lemma(s.low[j])
        if head in _COURSE_HEADS and not _names_a_place(s, head) and j > k and \
                (j + 1 >= s.n or s.w[j + 1].pos not in ("NOUN", "PROPN") or verb_before_particle(s, j + 1)
                 or heading_before_where_to(s, j + 1)):  # "on the Saturday lesson head for ...": a verb
            return True
        j += 1
    return False


def _names_a_place(s: Sentence, head: str) -> bool:
    """Whether the world calls a place by the head alone ("the course" of a racecourse)."""
    match = s.index.match([head])
    return match is not None and match.exact
