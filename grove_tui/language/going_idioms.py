"""Going said by an idiom (round 34).

- "make for the library" after a participle's object ("three sixth-formers doing coursework make for
  the library"): the parser takes "make" for a noun the object compounds with; before "for" and a
  determiner, or before "their way", "a beeline", "tracks", a form of "make" right after a noun is the
  clause's verb, and `as_going_verbs` tags it so. An adverb between ("make straight for the exit",
  "made directly for the lifts"), which the parser takes for an adjective "make" makes, is tagged the
  adverb it is (round 49), as it is after "head".
- "set off for", "set out for", "set off towards", "start off for", "strike out for": going there, as
  "head for" is (`setting_out`); "set off the alarm" and "set out the chairs" are not going.
"""

from __future__ import annotations

from dataclasses import replace

from grove_tui.language.parser import Word
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import verb_lemma

_MAKE_FORMS = frozenset("make makes made making".split())
# What follows "make" when it says going: "make for the", "make their way", "make a beeline", "make tracks".
_AFTER_FOR = frozenset("the a an this that their his her its our my".split())
_GOING_OBJECTS = frozenset("way beeline dash run bolt tracks break".split())
_POSSESSIVE = frozenset("their his her its our my a an".split())
_STRAIGHT = frozenset("straight directly".split())

# "set off for", "strike out for", "start off towards": a verb, its particle, and where to.
_SETTING_VERBS = frozenset("set start strike".split())
_SETTING_PARTICLES = frozenset({"off", "out"})
_TOWARDS = frozenset("for to towards toward into".split())


def _says_going(words: list[Word], k: int) -> bool:
    """Whether the words after "make" at k say going ("for the ...", "their way", "tracks for")."""
    nxt = words[k + 1].lower if k + 1 < len(words) else ""
    after = words[k + 2].lower if k + 2 < len(words) else ""
    if nxt == "for":
        return after in _AFTER_FOR
    if nxt == "tracks":
        return after in ("for", "to", "towards")
    return nxt in _POSSESSIVE and after in _GOING_OBJECTS


def as_going_verbs(words: list[Word]) -> list[Word]:
    """The parse with a form of "make" that says going, taken for a noun after a noun ("coursework make
    for the library"), tagged as the verb it is."""
    out = list(words)
    for k, w in enumerate(words[:-1]):
        if w.lower in _MAKE_FORMS and words[k + 1].lower in _STRAIGHT and _says_going(words, k + 1):
            out[k + 1] = replace(words[k + 1], pos="ADV", tag="RB", dep="advmod", head=k)  # "make straight for"
    words = list(out)
    for k, w in enumerate(words):
        if k == 0 or w.lower not in _MAKE_FORMS or w.pos == "VERB" or not _says_going(words, k):
            continue
        prev = words[k - 1]
        if prev.pos not in ("NOUN", "PROPN", "PRON"):
            continue  # "the make for ..." is no clause
        out[k] = replace(w, pos="VERB", tag="VBD" if w.lower == "made" else "VBP", dep="ROOT", head=k)
        if prev.dep == "compound" and prev.head == k:
            out[k - 1] = replace(prev, dep=w.dep, head=w.head)  # the object the verb was taken for
    return out


def setting_out(s: Sentence, i: int) -> tuple[str, ...] | None:
    """The phrase of setting out for a place starting at the verb at i ("sets off for", "strike out
    towards"), or None."""
    if verb_lemma(s.low[i]) not in _SETTING_VERBS and s.verb(i) not in _SETTING_VERBS:
        return None
    if s.after_determiner(i) or i + 2 >= s.n:
        return None  # "a set off ...": no verb
    if s.low[i + 1] not in _SETTING_PARTICLES or s.low[i + 2] not in _TOWARDS:
        return None
    if s.low[i + 2] == "to" and i + 3 < s.n and s.w[i + 3].pos in ("VERB", "AUX"):
        return None  # "set out to find the café": a purpose, said by the place it comes to
    return tuple(s.low[i:i + 2])


def straight_for(s: Sentence, i: int) -> bool:
    """Whether "make" at i is followed by "straight for" or "directly for" ("make straight for the exit")."""
    return i + 2 < s.n and s.low[i + 1] in _STRAIGHT and s.low[i + 2] == "for"
