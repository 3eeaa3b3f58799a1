"""Going nowhere on a machine (round 33): "one walking on a treadmill", "two run on the running
machines", "a patient pedals on an exercise bike". Walking, running or cycling *on* a machine of
exercise keeps people where the machine is: the machine is their location, not a start they leave."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

from grove_tui.language import lexicon as lx

from grove_tui.language.tokens import phrase_lemmas

if TYPE_CHECKING:
    from grove_tui.language.place_phrases import Place

# Words of a machine people exercise on in place.
_MACHINES = frozenset("treadmill treadmills bike bikes cycle cycles trainer trainers stepper steppers ergo ergos "
                      "rower rowers".split())
_MACHINE_PHRASES = (("running", "machine"), ("rowing", "machine"), ("walking", "machine"), ("cycling", "machine"),
                    ("exercise", "bike"), ("cross", "trainer"), ("stair", "climber"))
# Verbs of going on foot or by pedal that a machine of exercise keeps in place.
_IN_PLACE_VERBS = frozenset("walk run jog sprint cycle pedal spin row stride plod trot march pound jog power "
                            "bike train exercise".split())


def on_a_machine(p: Place, verb: str) -> bool:
    """Whether the place phrase `p` is a machine of exercise that the verb `verb` (a lemma) is done on:
    "walking on a treadmill", "runs on the running machines"."""
    if p.written not in ("on", "") or p.prep != "on" or verb not in _IN_PLACE_VERBS:
        return False
    words = [w.lower() for w in p.words]
    lemmas = set(phrase_lemmas(words)) | set(words)
    if lemmas & _MACHINES:
        return True
    return any(tuple(words[k:k + 2]) in _MACHINE_PHRASES or tuple(words[k:k + 2])[:1] + (words[k + 1].rstrip("s"),)
               in _MACHINE_PHRASES for k in range(len(words) - 1))


def stays_on_a_machine(p: Place, verb: str, places: Sequence[Place]) -> bool:
    """Whether people on the machine `p` stay there: no place after it they go to ("jogs on a treadmill
    for ten minutes, then goes to the changing rooms": the treadmill is where they start)."""
    return on_a_machine(p, verb) and not any(
        q.index > p.index and (q.prep in lx.DESTINATION_PREPOSITIONS or q.prep == "obj:dest") for q in places)
