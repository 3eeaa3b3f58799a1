"""Fleeing off to a place when the robot comes (round 51): "scurries off to the far corner once the robot
appears", "Terrified, a toddler runs off into the toilets when the robot rolls in". `robot_idioms` reads
"scurries off" timed by the robot as avoiding it only when the clause ends there ("not go back to"): a
going off to a place may be an errand. It is fleeing when the verb is one of fright (scurry, scuttle,
scarper, bolt, flee) or a word of fear stands before the subject ("Terrified, ..."), and the place
phrase is all that follows before the robot's time word."""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from grove_tui.language.sentence import Sentence

# Verbs of going that say fright on their own.
_FRIGHTENED_GOING = frozenset("scurry scuttle scamper scarper flee bolt dart skedaddle".split())
# Verbs of hurrying that are fleeing when a fear is said before the subject.
_HURRYING = _FRIGHTENED_GOING | frozenset("run rush hurry dash race scoot hare leg scramble".split())
_FEARS = frozenset("scared frightened afraid fearful terrified petrified spooked alarmed panicked panicking "
                   "panicky nervous unnerved".split())
_TOWARDS = frozenset("to into towards toward for behind under".split())
# Words that end the place phrase: the robot's time words and clause words.
_ENDS = frozenset("as when whenever once the-moment and but while".split())


def flees_to_a_place(s: Sentence, i: int, tail: int) -> bool:
    """Whether the verb at i with "off" or "away" at `tail` goes to a place, fleeing (see the module doc)."""
    if s.low[tail] not in ("off", "away") or tail + 1 >= s.n or s.low[tail + 1] not in _TOWARDS:
        return False
    v = s.verb(i) if s.w[i].pos in ("VERB", "AUX") else s.w[i].lemma
    feared = any(s.low[k] in _FEARS for k in range(0, i)) and any(s.is_punct(k) for k in range(0, i))
    if v not in _FRIGHTENED_GOING and not (v in _HURRYING and feared):
        return False
    for k in range(tail + 2, min(tail + 9, s.n + 1)):
        if k == s.n or s.is_punct(k) or s.low[k] in _ENDS:
            return k > tail + 2
        if s.w[k].pos in ("VERB", "AUX"):
            return False
    return False
