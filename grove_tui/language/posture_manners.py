"""How people go, said between a verb of walking and whom they go after (round 70): "a tiny lad shuffles
on his knees after the robot", "a toddler crawls on all fours towards it", "the kids creep on tiptoe
behind the robot". The readers of following and going up to someone look for "after", "behind",
"up to" ... right after the verb; the posture between says only how they go, so it is dropped before
the sentence is parsed ("shuffles after the robot")."""

from __future__ import annotations

import re

_POSTURE = re.compile(
    r"\s+on\s+(?:(?:his|her|their|its|my|our|your|one's)\s+)?(?:(?:hands\s+and\s+)?knees|all\s+fours|tip-?toes?|"
    r"bottoms?|bums?|backsides?|bellies|belly|tummy|tummies)(?=\s+(?:after|behind|towards|toward|up\s+to|over\s+to|"
    r"across\s+to|along\s+(?:after|behind))\b)", re.I)


def without_posture_before_going(text: str) -> str:
    """The text without a posture ("on his knees", "on all fours") between a verb and "after", "behind",
    "towards", "up to" ... ("shuffles on his knees after the robot": "shuffles after the robot")."""
    return _POSTURE.sub("", text)
