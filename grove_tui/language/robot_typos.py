"""The robot's name mistyped (round 69): "scared of the robto", "follows the roobt", "waves at the
robbot", "teh robot waits". The chat names (robot_chat.py) list a few short forms; a hurried keyboard
makes any slip of one letter: two letters swapped, one dropped, doubled or struck wrong. A word one
such slip from "robot" or "robots" that is no English word ("root", "roots" are kept) is the robot,
written out before any pass looks for it, and "teh"/"hte" right before it is "the" (chat_slips.py
writes the other swapped small words out only later, after the robot's own passes). A bare "bot" opening a
clause ("bot on standby @ the front desk, ...") is written "robot": the parser takes a "bot" there for a verb."""

from __future__ import annotations

import re

_TARGETS = ("robot", "robots")
# Real words (and a name) one slip from the robot's name.
_KEPT = frozenset({"root", "roots", "robots", "robot", "robo", "abbot"})
_WORD = re.compile(r"(?<![\w'@&/-])([A-Za-z]{4,7})(?![\w'@&/-])")
_BARE_BOT = re.compile(r"(^|[.;:!?,]\s*|\b(?:and|then|while|whilst|but|so|n|&)\s+)(bot|Bot|BOT)(?=\s+[A-Za-z@])")
_SWAPPED_THE = re.compile(r"(?<![\w'@&/-])(teh|hte)(\s+)(?=robots?\b)", re.IGNORECASE)


def _one_slip(word: str, target: str) -> bool:
    """Whether word is target with two neighbouring letters swapped, or one letter dropped, added or
    struck wrong (not the first letter struck wrong: "bobot" is too far from a typed "r")."""
    if word == target:
        return False
    n, m = len(word), len(target)
    if n == m:
        diff = [k for k in range(n) if word[k] != target[k]]
        if len(diff) == 1:
            return diff[0] > 0
        return len(diff) == 2 and diff[1] == diff[0] + 1 and word[diff[0]] == target[diff[1]] \
            and word[diff[1]] == target[diff[0]]
    if abs(n - m) != 1:
        return False
    longer, shorter = (word, target) if n > m else (target, word)
    return any(longer[:k] + longer[k + 1:] == shorter for k in range(len(longer)))


def _robot(m: re.Match[str]) -> str:
    typed = m.group(1)
    low = typed.lower()
    if low in _KEPT or not low.startswith(("r", "o")):
        return typed
    for target in _TARGETS:
        if _one_slip(low, target):
            if target == "robot" and low.endswith("s") and _one_slip(low, "robots"):
                target = "robots"
            return target.capitalize() if typed[0].isupper() else target
    return typed


def with_robot_spelt(text: str) -> str:
    """The text with each one-slip spelling of the robot's name written "robot" (module doc)."""
    text = _SWAPPED_THE.sub(lambda m: ("The" if m.group(1)[0].isupper() else "the") + m.group(2),
                            _WORD.sub(_robot, text))
    return _BARE_BOT.sub(lambda m: m.group(1) + ("robot" if m.group(2) == "bot" else "Robot"), text)
