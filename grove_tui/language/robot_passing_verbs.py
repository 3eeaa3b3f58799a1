"""The robot passing people said by the verb alone (round 40): "the robot passes the queue on its way to
security", "overtakes them on the way to the pharmacy", "skirts the crowd at the fountain". Said with a
preposition ("rolls past the queue", "weaves through them") it is read by language/robot_crowds.py;
said by a verb whose object is the people, the people are passed just the same."""

from __future__ import annotations

from grove_tui.language.sentence import Sentence

# Verbs whose object is what the robot goes by: "passes the queue", "overtakes the pair", "skirts the crowd".
_PASSING_VERBS = frozenset("pass overtake skirt bypass circumvent".split())


def passing_verb(s: Sentence, i: int) -> bool:
    """Whether word i is a verb of going by whose object follows it ("passes the queue", "overtaking
    them"), not "passes through" or "passes by", which the preposition says."""
    if s.verb(i) not in _PASSING_VERBS or (s.w[i].pos not in ("VERB", "AUX") and not s.w[i].tag.startswith("VB")):
        return False
    return i + 1 < s.n and s.preposition(i + 1) is None
