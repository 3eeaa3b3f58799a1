"""Words of a group's clause that cannot be its act on the robot: a word inside a hyphenated compound
("queue at the check-in counters", "a drop-off point") or inside the name of a place the world has
("wait by the check in desk"), which the parser may tag a verb all the same."""

from __future__ import annotations

from typing import TYPE_CHECKING

from grove_tui.language import lexicon as lx
from grove_tui.language.tokens import lemma

if TYPE_CHECKING:
    from grove_tui.language.sentence import Sentence


def in_place_name(s: Sentence, i: int) -> bool:
    """Whether the word at i is part of a compound ("check-in") or of a place's name: a place word of the
    world right before a noun the world knows too ("both check in counters")."""
    if (i + 1 < s.n and s.hyphen_inside(i + 1)) or (i > 0 and s.hyphen_inside(i - 1)):
        return True
    k = i + 1
    if k < s.n and s.low[k] == "in" and k + 1 < s.n:
        k += 1  # "check in counters", said without the hyphen
    return s.index.knows(lemma(s.low[i])) and k < s.n and s.w[k].pos in ("NOUN", "PROPN") and \
        s.index.knows(lemma(s.low[k])) and s.low[k] not in lx.ROBOT_WORDS


# Verbs of speaking, an act on the robot only when it is whom they speak to, right after them ("ask it
# for directions", "chat with the robot", "talk to it"), not "chat on the benches while the robot ...".
SPEAKING_VERBS = frozenset("ask talk chat speak question consult query hail thank".split())
_TO_WHOM = frozenset({"to", "with", "at", "the", "this", "that", "a"})


def speaks_elsewhere(s: Sentence, i: int, r: int) -> bool:
    """Whether the verb at i is one of speaking that does not speak to the robot at r."""
    return s.verb(i) in SPEAKING_VERBS and not all(s.low[k] in _TO_WHOM for k in range(i + 1, r))
