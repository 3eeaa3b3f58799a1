"""What a group that reacts to the robot does besides reacting: its routine.

"Six patients queue at the pharmacy and look at the robot as it passes" is a group of intent "robot"
(interaction "look") whose routine is "queue" at the pharmacy; "four visitors wait in the cafeteria for ten
seconds and avoid the robot" waits there; "three nurses walk to ward A and keep away from the robot" walk
there. The routine is the clause's own verb of walking, queuing, waiting, wandering or chatting when a
joiner ("and", "while", "as", a comma before a participle) or another verb stands between it and the
robot: "a man walks up to the robot", "two children walk away from the robot" or "a visitor chats to
the robot" is the reaction itself. A routine needs what it is done at: a walk its destination (or a
way through), a queue its place; a wait or a chat stays where the group is.
"""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.clauses import Clause
from grove_tui.language.model import ROUTINES, FieldConfidence
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import verb_lemma

# Words that join the routine to the reaction ("queue ... and look at the robot", "walk ... while avoiding it").
_JOINERS = frozenset({"and", "while", "whilst", "as", "then", ",", ";", "before", "after", "when", "but"})


def routine_beside_reaction(s: Sentence, c: Clause, scene: Clause | None, span: tuple[int, int],
                            robot: str | None, places: dict[str, str | None], via: tuple[str, ...] | list[str],
                            wait_seconds: float | None) -> tuple[str | None, list[FieldConfidence]]:
    """The routine of a group that reacts to the robot, and how sure the reader is of it (see the module
    doc); (None, []) for a group that only reacts."""
    if robot is None:
        return None, []
    routine, at, confidence = None, None, []
    if c.intent in ROUTINES and c.verb_index is not None:
        routine, at = c.intent, c.verb_index
        if not _apart_from_reaction(s, at, span):
            return None, []
    elif c.intent is None and scene is not None and scene.intent in ROUTINES and scene.verb_index is not None \
            and not span[0] <= scene.verb_index < span[1]:
        # "Queuing at the pharmacy, five patients glance at the robot": the sentence's opening clause
        routine = scene.intent
        confidence.append(FieldConfidence("routine", 0.75, "read from the words before the group, not its own"))
    if routine is None:
        return None, []
    if at is not None and lx.ROBOT_VERBS.get(verb_lemma(s.low[at])) == "follow":
        return None, []  # "follows the nurse to the exit and stares at the robot": a follower, not a walk
    if routine == "walk" and not (places.get("destination") or via):
        return None, []  # "walks in and stares at the robot": nowhere to walk to but the reaction
    if routine == "queue" and not places.get("location"):
        return None, []
    if routine == "wander" and not (places.get("location") or places.get("destination")):
        return None, []
    if routine == "wait" and not (places.get("location") or wait_seconds):
        return None, []  # "visitors stop and stare": staying is the look itself
    if routine == "wait" and robot == "block" and not wait_seconds:
        return None, []  # "two guards stand at the desk and block the robot": the stay is the block, held there
    return routine, confidence


def _apart_from_reaction(s: Sentence, verb: int, span: tuple[int, int]) -> bool:
    """Whether a joiner or another verb stands between the routine's verb and the robot (or, with no robot
    word in the group's words, anywhere after the verb): then the verb is not the reaction's own."""
    end = next((i for i in range(verb + 1, span[1]) if s.low[i] in lx.ROBOT_WORDS), None)
    if end is None:
        end = span[1]
    for i in range(verb + 1, end):
        if s.low[i] in _JOINERS:
            return True
        if s.w[i].tag.startswith("VB") and verb_lemma(s.low[i]) in lx.ROBOT_VERBS:
            return True  # "queue at the pharmacy watching the robot"
    # the robot's clause ends the group's words ("... and glance at it as it passes")
    return end == span[1] and any(s.low[i] in _JOINERS for i in range(verb + 1, span[1]))
