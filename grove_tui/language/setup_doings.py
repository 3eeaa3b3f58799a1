"""What someone set up in an order is doing, said before their place ("Have one porter folding sheets in
the laundry and two kids in the yard"): the small parser took the "-ing" words for a clause of their
own and lost the first group, while the same order with the doing said after the place ("one porter in
the laundry folding sheets") reads both. Written before parsing in that order. Only inside an order
opening "Have"/"Put"/"Place", for a counted person whose place phrase ends where another counted
group ("and two kids") begins."""

from __future__ import annotations

import re

from grove_tui.language import lexicon as lx

_NUMBER = "|".join(sorted((w for w in lx.NUMBER_WORDS if w.isalpha()), key=len, reverse=True))
_COUNT = r"(?:a|an|one|\d+|" + _NUMBER + r")"
_DOING = re.compile(
    r"(^|[.!?;]\s+)((?:Have|Put|Place)\s+" + _COUNT + r"\s+[a-z]+)\s+([a-z]+ing(?:\s+(?!the\b|a\b|an\b)[a-z]+)?)\s+"
    r"((?:in|at|by|on|near|beside|inside)\s+(?:the|a|an|their|his|her)\s+[^,.;]+?)(?=\s+and\s+" + _COUNT + r"\s)",
    re.IGNORECASE)


def with_setup_doings_after(text: str) -> str:
    """The text with a set-up person's doing said after their place (module doc)."""
    return _DOING.sub(lambda m: f"{m.group(1)}{m.group(2)} {m.group(4)} {m.group(3)}", text)
