"""A queue said as a line with its length (round 37): "the line at the admissions desk is forty strong",
"the queue for the tills is about thirty people long", "the queue outside the café is 20 deep". The line
is the people in it, that many of them queueing at its place: "forty people queue at the admissions
desk". What the line then does as a line ("and snakes back past the lockers", "stretching to the
doors") is its shape, not a walk of its people, and is dropped.
"""

from __future__ import annotations

import re

from grove_tui.language import lexicon as lx

_NUMBER = r"(?:\d+|" + "|".join(sorted((w for w in lx.NUMBER_WORDS if w.isalpha() and w not in
                                        ("couple", "pair", "handful", "dozens", "few", "several", "many")),
                                       key=len, reverse=True)) + \
    r")(?:-(?:one|two|three|four|five|six|seven|eight|nine|odd))?"
_APPROX = r"(?:about|around|roughly|some|nearly|almost|over|more than|at least|easily|a good)"
_PREP = r"(?:at|for|by|outside|inside|in front of|beside|near|next to|in|to|into|of)"
_LINE = re.compile(
    r"\b(?:[Tt]he|[Tt]his|[Tt]hat|[Aa])\s+(?:long\s+|snaking\s+|slow\s+)?(?:queue|line)"
    r"(?:\s+(?P<prep>" + _PREP + r")\s+(?P<place>[^,.;!?]+?))?"
    r"\s+(?:is|'s|was|stands at|has grown to|has reached|now stands at|runs to)\s+(?:now\s+|already\s+|still\s+)?"
    r"(?P<approx>" + _APPROX + r"\s+)?(?P<n>" + _NUMBER + r")\s+(?:people\s+|persons\s+|bodies\s+)?"
    r"(?:strong|deep|long)\b", re.IGNORECASE)
# What the line does as a line after its length: its shape, up to the clause's end.
_SHAPE_VERBS = ("snake|stretch|reach|run|wind|curl|extend|trail|tail|spill|coil|loop|go|back|string")
_SHAPE = re.compile(r"^(?:,?\s+and|,)\s+(?:(?:now|already|even)\s+)?(?:" + _SHAPE_VERBS + r")(?:s|es|ing)?\b[^,.;!?]*",
                    re.IGNORECASE)


def with_queue_lengths(text: str) -> str:
    """The text with "the line at X is forty strong" said as "forty people queue at X" (see the module
    doc)."""
    out: list[str] = []
    at = 0
    for m in _LINE.finditer(text):
        if m.group("prep") and m.group("prep").lower() == "of":
            continue  # "the line of people is ..." said otherwise; "a line of ten" is read already
        out.append(text[at:m.start()])
        approx = (m.group("approx") or "").strip()
        said = f"{approx} {m.group('n')} people queue".strip()
        if m.group("place"):
            said += f" {m.group('prep')} {m.group('place')}"
        if m.start() == 0 or re.search(r"[.!?]\s*$", text[:m.start()]):
            said = said[:1].upper() + said[1:]
        out.append(said)
        at = m.end()
        shape = _SHAPE.match(text[at:])
        if shape:
            at += shape.end()
    out.append(text[at:])
    return "".join(out)
