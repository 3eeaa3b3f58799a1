"""Role words no list holds, joined by "and" to another person before their verb: "the drummer and
bassist haul their amps in ...", "the curator and the restorer walk ...", "the singer and the drummer
...". A word made as names for people are ("-er", "-or", "-ist", "-ant", "-ee", "-eer":
language/role_suffixes.py) is a person where it stands as a subject; the small parser calls the first
of two such words a modifier ("drummer" an nmod of "bassist") or the second a bare conjunct, and
neither was read as anyone, so the sentence gave a vague crowd or lost the second person. Here a word
so made is a person when "and" joins it to a person word (a listed one or one made the same way) and
the two stand before the clause's verb, the first opened by a determiner or a possessive.
"""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.role_suffixes import role_shaped
from grove_tui.language.sentence import Sentence

_OPENERS = frozenset("the a an both our their his her my your its this that these those".split())


def _listed(s: Sentence, i: int) -> bool:
    return s.w[i].pos in ("NOUN", "PROPN") and (s.lemma(i) in lx.PERSON_NOUNS or s.low[i] in lx.PERSON_NOUNS)


def _person_word(s: Sentence, i: int) -> bool:
    return 0 <= i < s.n and (_listed(s, i) or role_shaped(s, i))


def _opened(s: Sentence, i: int) -> bool:
    return i > 0 and (s.low[i - 1] in _OPENERS or s.low[i - 1] in ("'s", "’s"))


def _verb_after(s: Sentence, i: int) -> bool:
    """Whether a finite verb follows word i; the small parser may call it a noun ("the drummer haul
    their amps"), told then by a determiner, possessive or preposition right after it."""
    if i + 1 >= s.n:
        return False
    if s.w[i + 1].pos in ("VERB", "AUX"):
        return s.w[i + 1].tag in ("VBP", "VBD", "VBZ", "VB", "MD")  # "... and radiographer wait": VB
    return s.w[i + 1].tag == "NN" and i + 2 < s.n and not s.index.knows(s.lemma(i + 1)) and \
        (s.low[i + 2] in _OPENERS or s.low[i + 2] in lx.PLACE_PREPOSITIONS)


def coordinated_role(s: Sentence, i: int) -> bool:
    """Whether word i, a role word by its ending, is a person joined by "and" to another person word
    before the clause's verb (see the module doc)."""
    if not role_shaped(s, i, adjective=True):  # "the concierge and the sommelier walk": an adjective
        return False
    # i second: "A and B", "A and the B"
    j = i - 1 - (1 if i >= 1 and s.low[i - 1] in _OPENERS else 0)
    if j >= 1 and s.low[j] == "and" and _person_word(s, j - 1) and _opened(s, j - 1) and _verb_after(s, i):
        return True
    # i first: "A and B", "A and the B"
    if not (_opened(s, i) and i + 2 < s.n and s.low[i + 1] == "and"):
        return False
    k = i + 3 if s.low[i + 2] in _OPENERS else i + 2
    return _person_word(s, k) and _verb_after(s, k)
