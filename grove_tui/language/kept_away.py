"""A place kept away from, said by a participle (probe round r64c): "the robot goes to the server room,
keeping away from the kitchen", "staying well clear of the lobby". The bare "from" made the place the
mover's start; the phrase says a place not to use, as "avoiding the kitchen" does, and is read so.
Only a place: "keeping away from the robot" (or "it", "them") is a reaction and is left alone.

The other ways of saying it are read the same way (they made the place a start, a stop on the way or
nothing): "keeps out of the cafeteria", "steers clear of the food court", "without going through the
main waiting room", "without entering the lobby", "never enters the kitchen", "never goes near the
lifts", "must not enter the lobby", and the robot's own "avoids the cafeteria". The clause reader then takes "avoiding the X" as a place not to use (`clauses._not_using`) for
whoever the clause is about, a group or the robot; a phrase that names no place is left as it was read.
"""

from __future__ import annotations

import re

# What may follow: a place's words, not the robot, a pronoun for someone, or "the way" ("keep out of the way").
_NOT_SOMEONE = (r"(?!(?:the\s+|a\s+|an\s+|its\s+)?(?:robot|robots|machine|bot|way|path)\b|it\b|them\b|him\b|her\b|"
                r"us\b|me\b|you\b|each\b|one\s+another\b|sight\b|trouble\b|harm'?s?\b)")
_KEPT_AWAY = re.compile(
    r"\b(?:keeping|staying|steering|keep|stay|keeps|stays|kept|stayed|steer|steers|steered)\s+(?:well\s+|right\s+)?"
    r"(?:away\s+from|clear\s+of|out\s+of)\s+"
    r"(?=(?:the|a|an|any)\s+(?!robot\b|robots\b|machine\b|bot\b|way\b|path\b))",
    re.IGNORECASE)
_MOVING = r"(?:going|passing|cutting|driving|travell?ing|moving|rolling|heading|walking|wandering|venturing|straying|getting|stepping|setting\s+foot)"
_WITHOUT = re.compile(
    r"\bwithout\s+(?:ever\s+)?(?:" + _MOVING + r"\s+(?:through|thru|via|into|in\s+to|inside|across|near|past|by|in)"
    r"|entering|crossing|using|visiting|passing(?:\s+through)?)\s+" + _NOT_SOMEONE,
    re.IGNORECASE)
_NEVER = re.compile(
    r"(?:\bnever|\bnot|n['’]t)\s+(?:once\s+|ever\s+)?(?:(?:enters|entering|entered|enter)"
    r"|(?:goes|going|went|go|drives|driving|drove|drive|passes|passing|passed|pass|rolls|rolling|rolled|roll|"
    r"strays|straying|strayed|stray|ventures|venturing|ventured|venture)\s+(?:through|thru|via|into|inside|near|in))"
    r"\s+" + _NOT_SOMEONE,
    re.IGNORECASE)

# The robot's own verb of avoiding ("the robot must avoid the cafeteria on its way to the pharmacy"); a person's
# "avoid" is left to the reactions ("two nurses avoid the crowd").
_ROBOT_AVOIDS = re.compile(
    r"\b((?:robot|bot|droid)\s+(?:(?:must|should|will|shall|can|has\s+to|needs\s+to|is\s+to|always|carefully|then|"
    r"also)\s+){0,2})(?:avoid|avoids|avoided|shun|shuns|shuned|bypass|bypasses|bypassed)\s+"
    r"(?=(?:the|a|an|any)\s+(?!robot\b|robots\b|machine\b|bot\b|way\b|path\b))",
    re.IGNORECASE)


def kept_away(text: str) -> str:
    """The text with "keeping away from the X" (and the module doc's other wordings) said as
    "avoiding the X" for a place X."""
    text = _ROBOT_AVOIDS.sub(r"\1avoiding ", text)
    text = _WITHOUT.sub("avoiding ", _KEPT_AWAY.sub("avoiding ", text))
    # "doesn't go through the X": "does avoiding the X", not "doesavoiding"
    return _NEVER.sub(lambda m: " avoiding " if m.group(0)[:2].lower() in ("n'", "n’") else "avoiding ", text)
