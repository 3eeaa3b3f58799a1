"""The robot sent somewhere, said in the passive (round 45): "The robot is sent from the pharmacy up to
ward B", "the robot was dispatched to the gate", "the bot gets directed over to reception". Nobody who
sends it is in the scene, and the robot's clause was lost: the robot is read as going there itself
("the robot goes from the pharmacy up to ward B"), a crossing like any other robot's clause."""

from __future__ import annotations

import re

# The robot, a passive "be" or "get", and a verb of sending, before where it goes ("to", "from", "up", ...).
_SENT = re.compile(r"\b((?:the|our|a|its)\s+(?:robot|bot))\s+(?:is|was|gets|got|has\s+been|had\s+been|is\s+being)\s+"
                   r"(?:sent|dispatched|despatched|directed|routed|ordered|summoned|called)\b(?=\s+(?:off\s+|out\s+|"
                   r"back\s+|over\s+|up\s+|down\s+|across\s+|round\s+|along\s+)?(?:to|from|into|towards?|up|down|over|across)\b)",
                   re.IGNORECASE)


def robot_sent(text: str) -> str:
    """The text with the robot sent somewhere in the passive said as the robot going there (module doc)."""
    return _SENT.sub(lambda m: f"{m.group(1)} goes", text)
