"""A named person said with the group they belong to in apposition (round 28): "Kayleigh, one of the
lifeguards, leaves the crew room", "Dr Shah, one of our vets, walks ...". The parser made the name,
the group ("the lifeguards") and its one member three groups; the apposition only says who the
named person is, so it is left out before the sentence is read: "Kayleigh leaves the crew room", one
person. Only a capitalised name (with a title, or a second capitalised word) before ", one of
the/our/their/... <words>," is read so; "one of the guards walks" (no name before it) is untouched."""

from __future__ import annotations

import re

from grove_tui.language import lexicon as lx
from grove_tui.language.named_roles import _a_name

_MEMBER = re.compile(r"(?<![\w'’-])((?:[A-Z][a-z]{0,8}\.? )?[A-Z][a-z]+(?: [A-Z][a-z]+)?)"
                     r",\s+(?:one|another|the (?:eldest|youngest|oldest|newest|tallest))\s+of\s+"
                     r"(?:the|our|their|his|her|its|my|your|them)\b[^,.;:!?]{0,40},\s*")


def without_apposed_members(text: str) -> str:
    """The text with ", one of the <group>," after a name left out (see the module doc)."""
    def cut(m: re.Match[str]) -> str:
        words = m.group(1).split()
        if not all(_a_name(w) or w.lower().rstrip(".") in lx.TITLES for w in words):
            return m.group(0)  # "Then, one of the guards, ...", "Meanwhile, one of ...": no name
        return f"{m.group(1)} "  # "Tom, one of the guards, and a cleaner": "Tom and a cleaner"
    return _MEMBER.sub(cut, text)
