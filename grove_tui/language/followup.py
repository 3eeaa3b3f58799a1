"""Follow-up sentences read against a scenario that exists: which groups to add, change or remove.

    edit = read_followup("make the queue twice as long", world, groups)      # groups: the scenario's GroupReadings
    edit.edits[0]   # GroupEdit(kind="change", target=GroupRef("the queue", (0,)), count=CountChange("factor", 2.0))

A small pass over the one reader (`read_prompt`): the follow-up modules find what kind of edit each
clause is and which groups it names; the people, counts, places, intents, robot interactions, pace and
waits are read by `read_prompt` itself. This module splits the sentence into clauses and hands each to
the readers of the edit kinds, in this order:

1. Clauses. The sentence is split at sentence ends and semicolons, and before an edit verb joined by
   "and"/"then" ("remove the cleaner and add two guards"). Words of conversation ("no,", "now",
   "ok") are dropped; "instead", "too", "as well" are kept as cues.
2. The robot (`followup_robot.py`): "no robot", "add a robot", "the robot waits at reception".
3. Removals and replacements (`followup_groups.py`): "remove two of the nurses", "replace the cleaner
   with a guard".
4. Counts (`followup_counts.py`): "twice as long", "make the queue longer", "only two nurses",
   "two fewer visitors".
5. Additions (`followup_groups.py`): "add ...", "plus ...", "... too", "another", "N more X".
6. Everything else is a change when its subject names a group of the scenario, else an addition
   (`followup_groups.py`).

Which groups a phrase names is `followup_references.resolve`; what every reader shares (the groups,
the notes, the reader) is `followup_context.FollowupContext`; the types are in `edits.py`.
"""

from __future__ import annotations

import re
from collections.abc import Sequence

from grove_tui.language.edits import EditReading, GroupEdit, RobotEdit
from grove_tui.language.followup_context import FollowupContext
from grove_tui.language.followup_counts import read_count_edit
from grove_tui.language.followup_groups import (read_addition, read_change_or_addition, read_removal,
                                                read_replacement)
from grove_tui.language.followup_phrases import DETERMINER_PATTERN, ROBOT_PATTERN
from grove_tui.language.followup_robot import read_robot_edit
from grove_tui.language.model import GroupReading
from grove_tui.world.model import World

_LEADING = re.compile(
    r"^(?:(?:no|nope|ok|okay|actually|now|then|and|but|so|well|oh|please|right|hmm|wait|sorry|instead|also|next|"
    r"finally|alright|good|great|fine|yes|yeah)\s*[,:;!-]\s*"
    r"|(?:now|then|and|but|so|please|actually|ok|okay|oh|right|well|next|finally|alright|hmm)\s+"
    r"|no\s+(?=(?:the|a|an|they|it|make|let|have|add|remove|instead|only)\b))")
_TRAILING = re.compile(r"(?:\s*,)?\s+(?:instead|too|as well|please|now|this time|again|then|also)\s*$")
_SPLIT_SENTENCES = re.compile(r"(?<=[.!?;])\s+|\s*;\s*")
_EDIT_START = (r"(?:add|also|plus|remove|delete|drop|get rid of|take (?:out|away)|make|let|have|double|halve|"
               rf"triple|replace|swap|send|put|place|move|no\s+{ROBOT_PATTERN}|{DETERMINER_PATTERN}\s+{ROBOT_PATTERN})\b")
_SPLIT_EDITS = re.compile(r"\s*(?:,\s*(?:and\s+(?:then\s+)?|then\s+)?|\s+and\s+(?:then\s+)?|\s+then\s+)"
                          r"(?=" + _EDIT_START + ")")


def read_followup(sentence: str, world: World, groups: Sequence[GroupReading], *, has_robot: bool = True,
                  seed: int = 0, last: Sequence[int] = ()) -> EditReading:
    """What a follow-up sentence asks to change in a scenario of `groups` (see the module doc).

    `has_robot`: whether the scenario has a robot now. `last`: the groups the previous edit touched, the
    groups "they" or "it" mean. `seed` settles vague counts ("a few more visitors") as the reader does."""
    text = " ".join((sentence or "").split())
    ctx = FollowupContext(world, tuple(groups), int(seed), tuple(last), has_robot, [], [])
    edits: list[GroupEdit] = []
    robot: RobotEdit | None = None
    for clause in _clauses(text):
        found, robot_edit = _read_clause(clause, ctx)
        edits.extend(found)
        if robot_edit is not None:
            robot = robot_edit
        first_new = ctx.group_count
        new = [e.group for e in found if e.kind == "add" and e.group is not None]
        ctx.added.extend(new)
        touched = tuple(t for e in found if e.kind != "add" and e.target is not None for t in e.target.targets)
        touched += tuple(range(first_new, first_new + len(new)))  # "add a cleaner, then make it walk slowly"
        if touched:
            ctx.last = touched
    if not edits and robot is None and text and not ctx.notes:
        ctx.notes.append("nothing in it adds, changes or removes a group or the robot")
    return EditReading(text, tuple(edits), robot, tuple(dict.fromkeys(ctx.notes)))


# ---- clauses --------------------------------------------------------------------------------------------

def _clauses(text: str) -> list[str]:
    out: list[str] = []
    for sentence in _SPLIT_SENTENCES.split(text):
        sentence = sentence.strip().rstrip(".!?;,").strip()
        if not sentence:
            continue
        for part in _SPLIT_EDITS.split(sentence.lower()):
            part = part.strip(" ,")
            if part:
                out.append(part)
    return out


def _clean(clause: str) -> tuple[str, set[str]]:
    """The clause without words of conversation, and the cues found ("instead", "add")."""
    cues: set[str] = set()
    text = clause.lower().strip(" .!?,")
    while True:
        m = _LEADING.match(text)
        if m is None:
            break
        word = m.group(0).strip(" ,:;!-")
        if word in ("instead", "also", "now"):
            cues.add("instead" if word in ("instead", "now") else "add")
        text = text[m.end():].strip()
    while True:
        m = _TRAILING.search(text)
        if m is None:
            break
        word = m.group(0).strip(" ,")
        cues.add("instead" if word in ("instead", "now", "this time") else "add" if word in ("too", "as well", "also")
                 else "")
        text = text[:m.start()].strip()
    cues.discard("")
    return text, cues


def _read_clause(clause: str, ctx: FollowupContext) -> tuple[list[GroupEdit], RobotEdit | None]:
    text, cues = _clean(clause)
    if not text:
        return [], None
    robot = read_robot_edit(text, ctx)
    if robot is not None:
        return [], robot
    for reader in (read_removal, read_replacement, read_count_edit, read_addition):
        found = reader(text, cues, ctx)
        if found is not None:
            return found, None
    return read_change_or_addition(text, cues, ctx), None
