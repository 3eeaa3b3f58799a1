"""The robot's patrol said as a state (round 46): "bot on patrol along the broad walk", "the robot is out on
patrol in the lobby", "robot on its rounds of the ward", "the robot stays on patrol by the gates";
round 53: doing them, "robot doing rounds", "the bot is doing laps of the yard"). No verb
of the robot's tasks is there, so its clause was read as nothing (or as the people's). The state is said
as the verb the reader knows: "robot is patrolling along the broad walk"; a verb of going before "on
patrol" ("the robot goes out on patrol round the car park") is the patrol itself. Only after the robot:
"a guard on patrol" is a person's own business, read as it is."""

from __future__ import annotations

import re

# The robot (its usual names: robot_chat.py writes the short ones out), up to one word of it ("the
# cleaning robot"), then an optional "is"/"stays"/a going verb, "out", and "on patrol" / "on its rounds".
_ON_PATROL = re.compile(
    r"(?P<robot>\b(?:robot|bot)\b)"
    r"(?P<verb>\s+(?:is|'s|stays|remains|keeps|was|will\s+be|should\s+be|goes|heads|sets\s+off|sets\s+out|"
    r"starts|begins|carries\s+on|continues))?"
    r"(?:\s+(?:out|off|still|already|busy|again|now))?"
    r"\s+(?:on|doing)\s+(?:(?:a|its|his|her|the|their|another|one\s+of\s+its)\s+)?(?:(?:slow|usual|regular|routine|"
    r"security|night|nightly|hourly|daily|normal|endless|lonely|first|next|last|final|quick)\s+)?"
    r"(?:patrols?|rounds|beat|circuits?|loops?|laps?)\b"
    r"(?:\s+(?:of|around|round)\b)?",
    re.IGNORECASE)


def on_patrol(text: str) -> str:
    """The text with the robot's patrol said as a state written as the verb (module doc)."""
    def said(m: re.Match[str]) -> str:
        return f"{m.group('robot')} is patrolling"
    return _ON_PATROL.sub(said, text)
