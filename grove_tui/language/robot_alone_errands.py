"""A robot's errand with nobody in it (round 54): "the robot brings a sack of ice up from the cellar to
the upstairs bar", "the robot carries a tray of glasses to the terrace". A sentence naming no people
was read as a scene the model fills in (one group of "people"); when the whole sentence is the robot
carrying a thing, from one place to another or to one, the sentence sets a robot task alone and no
group is made up. A crowd said anywhere ("a busy bar", "through the crowd") keeps the made-up group."""

from __future__ import annotations

from typing import TYPE_CHECKING

from grove_tui.language import lexicon as lx
from grove_tui.language.tokens import verb_lemma

if TYPE_CHECKING:
    from collections.abc import Sequence

    from grove_tui.language.people import People
    from grove_tui.language.robot import RobotClause
    from grove_tui.language.sentence import Sentence

# Verbs of carrying a thing along ("brings a crate", "carries a tray", "delivers a parcel").
_CARRYING = frozenset("take bring carry fetch ferry cart lug haul deliver transport wheel".split())
# Particles between the verb and its object ("brings up a crate").
_PARTICLES = frozenset("up down over across round around along back out in".split())
# Words that say people are about, so the made-up group stays ("a busy bar", "through the crowd").
_CROWD = frozenset("busy crowded packed heaving full crowd crowds rush throng bustling".split())


def a_robot_errand_alone(s: Sentence, people: People, found: Sequence[RobotClause]) -> bool:
    """Whether a sentence naming nobody is only the robot carrying a thing (no group to make up)."""
    if len(found) != 1 or found[0].verb is None or found[0].command:
        return False
    rc = found[0]
    verb = rc.verb
    assert verb is not None
    if verb_lemma(s.low[verb]) not in _CARRYING or any(w in _CROWD for w in s.low):
        return False
    covered = set(rc.tokens)
    if any(i not in covered and not s.is_punct(i) for i in range(verb, s.n)):
        return False  # more said after the robot's clause
    k = verb + 1
    while k < s.n and s.low[k] in _PARTICLES:
        k += 1
    if k >= s.n or s.low[k] not in lx.DETERMINERS:
        return False  # "brings them", "carries on": no thing said
    head = k + 1
    while head < s.n and s.w[head].pos in ("ADJ", "NOUN", "NUM") and head + 1 < s.n and \
            s.w[head + 1].pos in ("NOUN", "ADJ"):
        head += 1
    if head >= s.n or s.w[head].pos != "NOUN" or people.is_person_noun(head):
        return False
    if head + 2 < s.n and s.low[head + 1] == "of":  # "a sack of ice", "a crate of mixers", not "a group of kids"
        j = head + 2
        while j < s.n and s.w[j].pos in ("ADJ", "DET"):
            j += 1
        if j < s.n and people.is_person_noun(j):
            return False
    return True
