"""A person no list names, alone, in a second clause: "..., and a postdoc hangs about by the espresso
machine", "..., and a roadie waits by the bar". The parser often reads the unknown noun after "and a"
as an adjective and the verb after it as a plural noun ("a roadie waits" as "roadie waits"), so the
subject was never seen; and "hangs about" / "hangs around" is waiting, though a thing hangs too
(round 49)."""

from __future__ import annotations

from collections.abc import Callable

from grove_tui.language import lexicon as lx
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import verb_lemma

_IDLING_PARTICLES = frozenset({"about", "around", "round"})
_JOINERS = frozenset({"and", "while", "whilst", "as", "but"})


def hanging_about(s: Sentence, v: int) -> bool:
    """Whether verb v is "hang about" / "hang around": a person's waiting, not a thing's hanging."""
    return s.verb(v) == "hang" and v + 1 < s.n and s.low[v + 1] in _IDLING_PARTICLES


def _people_verb(s: Sentence, v: int) -> bool:
    low = s.low[v]
    if not low.isalpha() or not low.endswith("s") or low.endswith("ss"):
        return False  # the singular verb of one person: "waits", "hangs", "lingers"
    if verb_lemma(low) == "hang":
        return hanging_about(s, v)
    lem = verb_lemma(low)
    return lem != low and lem not in lx.THING_VERBS and (
        lem in lx.INTENT_VERBS or lem in lx.HUMAN_SUBJECT_VERBS or lem in lx.PEOPLE_GOING_VERBS)


def joined_lone_subject(s: Sentence, i: int, a_thing: Callable[[str], bool]) -> bool:
    """Whether word i, after "and a" / "while an", is one person no list names, by the singular
    verb of a person right after it (see the module doc)."""
    if i < 2 or i + 1 >= s.n or s.low[i - 1] not in ("a", "an") or s.low[i - 2] not in _JOINERS:
        return False
    word = s.low[i]
    if not word.isalpha() or len(word) < 4 or word.endswith("s") or s.w[i].pos not in ("NOUN", "ADJ", "PROPN"):
        return False
    if a_thing(word) or a_thing(s.lemma(i)) or word in lx.ROBOT_WORDS:
        return False
    return _people_verb(s, i + 1)
