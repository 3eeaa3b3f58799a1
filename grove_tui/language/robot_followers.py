"""People tied to the robot's own task (round 36), said so that the reader lost one side of the tie:

- a participle of following on the robot's clause, fronted or trailing ("Followed by a nurse, the robot
  drives to the ward", "The robot heads to the lifts, trailed by two porters"): the followers follow the
  robot, and the robot's clause is its own task; said as "a nurse follows the robot as the robot drives
  to the ward";
- a relative clause of the robot that follows or leads someone ("a porter follows the robot which
  follows a doctor"): the robot's own task, said as "..., and the robot follows a doctor";
- someone the robot picks up, meets or collects at a place and then escorts ("the robot picks up a
  visitor at the entrance and escorts them to the cafe"): one escort from that place, said as "the
  robot escorts a visitor from the entrance to the cafe".
"""

from __future__ import annotations

import re

_ROBOT = r"(?:the|a|an|our|its|their)\s+(?:[\w-]+\s+){0,2}?robot"
_FOLLOWED = r"(?:followed|trailed|tailed|shadowed|accompanied|chased|pursued)"
_ADVERB = r"(?:(?:closely|slowly|quietly|eagerly|nervously|cautiously|warily|loosely|hesitantly)\s+)?"

_FRONTED = re.compile(rf"^{_ADVERB}{_FOLLOWED}\s+{_ADVERB}by\s+(?P<who>[^,.;:!?]+?)\s*,\s+"
                      rf"(?P<rest>{_ROBOT}\b.+)$", re.IGNORECASE | re.DOTALL)
_TRAILING = re.compile(rf"^(?P<rest>{_ROBOT}\b[^.;:!?]+?)\s*,\s+(?:(?:and|while|as)\s+)?(?:it\s+is\s+|is\s+)?"
                       rf"{_ADVERB}{_FOLLOWED}\s+{_ADVERB}by\s+(?P<who>[^,.;:!?]+?)\s*(?P<end>[.!]?)\s*$",
                       re.IGNORECASE | re.DOTALL)
_RELATIVE = re.compile(rf"(?P<robot>\b{_ROBOT})\s*,?\s+(?:which|that|who)\s+(?:then\s+|in\s+turn\s+|itself\s+)?"
                       r"(?P<verb>follows|trails|tails|shadows|escorts|guides|leads|accompanies|chases)\b",
                       re.IGNORECASE)
_PICKED = re.compile(
    rf"(?P<robot>\b{_ROBOT})\s+(?:(?:first|then)\s+)?"
    r"(?:picks\s+up|collects|meets|greets|fetches|welcomes|finds)\s+(?P<who>(?!them\b|him\b|her\b)[^,.;:!?]+?)"
    r"(?:\s+up)?\s+(?:at|from|in|by|outside)\s+(?P<start>(?:the\s+)?[^,.;:!?]+?)\s*,?\s+and\s+(?:then\s+)?"
    r"(?:escorts|takes|brings|guides|leads|walks|shows|accompanies|ushers)\s+(?:them|him|her)\s+"
    r"(?:(?:over|across|back|down|up|through|on|along)\s+)?(?P<prep>to|into|towards|toward)\b",
    re.IGNORECASE)


def _lower_first(text: str) -> str:
    return text[:1].lower() + text[1:] if text[:1].isupper() and not text[1:2].isupper() else text


def _upper_first(text: str) -> str:
    return text[:1].upper() + text[1:]


def with_robot_followers(text: str) -> str:
    """The text with followers of the robot, its relative follow and a pick-up then escort said plainly
    (module doc); any other text as it is."""
    m = _FRONTED.match(text)
    if m is None:
        m = _TRAILING.match(text)
    if m is not None and " robot" not in m.group("who").lower():
        rest = m.group("rest").rstrip()
        end = m.groupdict().get("end") or ""
        text = f"{_upper_first(m.group('who').strip())} follows the robot as {_lower_first(rest)}{end}"
    text = _RELATIVE.sub(lambda r: f"{r.group('robot')}, and the robot {r.group('verb')}", text)
    return _PICKED.sub(lambda p: f"{p.group('robot')} escorts {p.group('who')} from {p.group('start')} "
                                 f"{p.group('prep')}", text)
