"""A fronted clock time before a name (round 26): "At nine Tom Hale walks to ...", "By 10.30 Dr Patel
is ...", "Around eleven Mrs Oakes ...". The number says when, not how many: a comma after the time
(as "At nine, Tom Hale walks") keeps it from being read as a count of the named person.
"""

from __future__ import annotations

import re

_HOURS = "one|two|three|four|five|six|seven|eight|nine|ten|eleven|twelve|noon|midnight"
_CLOCK = re.compile(
    r"(^|[.;!?]\s+)((?:at|by|around|about|after|before|until|till|from|just after|just before|shortly after|"
    r"soon after|roughly at|at about|at around|come)\s+"
    r"(?:(?:\d{1,2}(?:[:.]\d{2})?|" + _HOURS + r")(?:\s*(?:am|pm|a\.m\.|p\.m\.|o'clock|oclock|"
    r"thirty|fifteen|forty-five|sharp))?))\s+(?=(?:Mr|Mrs|Ms|Miss|Dr|Prof|Sir|Dame|Lady|Lord|[A-Z][a-z]+)\b)",
    re.IGNORECASE)
# Words that start a clause after the time but are no name ("At nine The doors open" is rare; the
# capitalised sentence words that follow a fronted time are pronouns and determiners).
_NOT_NAMES = frozenset("the a an some two three four five six seven eight nine ten eleven twelve twenty thirty "
                       "forty fifty all every each most many few several his her their our my your its this that "
                       "these those they he she we i it there everyone everybody nobody".split())


_APPROXIMATE = frozenset("about around roughly".split())
_TITLES = frozenset("mr mrs ms miss dr prof sir dame lady lord".split())
_TAIL = re.compile(r"\d[:.]\d|am$|pm$|a\.m\.$|p\.m\.$|o'?clock$|sharp$")


def with_clock_commas(text: str) -> str:
    """The text with a comma after a fronted clock time that a capitalised name follows."""
    def comma(m: re.Match[str]) -> str:
        nxt = text[m.end():].split(" ", 1)[0].strip(",.").lower()
        if nxt in _NOT_NAMES or not text[m.end():m.end() + 1].isupper():
            return m.group(0)
        said = m.group(2).lower()
        if said.split()[0] in _APPROXIMATE and not _TAIL.search(said) and nxt not in _TITLES:
            return m.group(0)  # "About twelve Japanese tourists": a count; "around eleven Mrs Oakes": a time
        return f"{m.group(1)}{m.group(2)}, "
    return _CLOCK.sub(comma, text)
