"""Someone the robot has in tow (round 46): "With a frail pensioner in tow, the robot crosses from X to Y",
"the robot heads to the lifts with two porters in tow", "the robot, towing a lost child, drives to the
desk", "Towing a visitor, the robot ...". The person follows the robot while the robot does its own
task; read as nobody's interaction, they stood still. Said as the reader already reads a follower of the
robot (robot_followers.py): "Followed by a frail pensioner, the robot crosses ...", "the robot heads to the
lifts, followed by two porters". Only a person is so taken: "with its cart in tow" is a thing it pulls."""

from __future__ import annotations

import re

from grove_tui.language import lexicon as lx
from grove_tui.language.people import compound_person
from grove_tui.language.tokens import lemma

_ROBOT = r"(?:the|a|an|our|its|their)\s+(?:[\w-]+\s+){0,2}?(?:robot|bot)"
_WORDS = r"(?:[\w'-]+\s+){0,5}?[\w'-]+"
_TAKEN = rf"(?:with\s+(?P<who>{_WORDS})\s+in\s+tow|towing\s+(?P<twho>{_WORDS}))"
_FRONTED = re.compile(rf"^{_TAKEN}\s*,\s*(?P<rest>{_ROBOT}\b)",
                      re.IGNORECASE)
# "the robot, with X in tow, crosses ...", "the robot, towing X, crosses ...": the aside moves to the front.
_ASIDE = re.compile(rf"^(?P<robot>{_ROBOT})\s*,\s*{_TAKEN}"
                    r"\s*,\s*", re.IGNORECASE)
# "the robot heads to the lifts with X in tow.", "..., towing X.": at the end of a sentence of the robot.
_TRAILING = re.compile(rf"^(?P<rest>{_ROBOT}\b[^.;:!?]+?)\s*,?\s+{_TAKEN}\s*(?P<end>[.!]?)\s*$", re.IGNORECASE)


def _who(m: re.Match[str]) -> str | None:
    """The person taken along, if the words name a person."""
    who = m.group("who") or m.group("twho")
    words = who.lower().split()
    if any(lemma(w) in lx.PERSON_NOUNS or compound_person(lemma(w)) for w in words) or \
            any(tuple(words[k:k + 2]) in lx.MULTIWORD_PEOPLE for k in range(len(words))):
        return who
    return None


def with_robot_in_tow(text: str) -> str:
    """The text with a person the robot has in tow said as its follower (module doc); else as it is."""
    m = _FRONTED.match(text)
    if m is not None and (who := _who(m)) is not None:
        return f"Followed by {who}, {text[m.start('rest'):]}"
    m = _ASIDE.match(text)
    if m is not None and (who := _who(m)) is not None:
        return f"Followed by {who}, {m.group('robot')} {text[m.end():]}"
    m = _TRAILING.match(text)
    if m is not None and (who := _who(m)) is not None:
        return f"{m.group('rest').rstrip()}, followed by {who}{m.group('end')}"
    return text
