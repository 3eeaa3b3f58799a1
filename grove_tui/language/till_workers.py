"""People named by the till they work at (round 47): "a pair of till staff gossip behind the returns
desk", "two till operators chat by the kiosk", "the till girl waves". "Till" is also "until", and the
parser reads "two till staff" as a count cut off by a time word: the people are lost and, after a
robot clause, the rest of the sentence with them. A till before a person noun names the person's post,
so the two are joined before the sentence is parsed ("till-staff"), as "checkout staff" already reads.
"""

from __future__ import annotations

import re

from grove_tui.language import lexicon as lx

_TILL_PERSON = re.compile(r"(?<![-\w'])(tills?)\s+([A-Za-z]+)\b", re.IGNORECASE)


def _person_word(word: str) -> bool:
    low = word.lower()
    forms = {low, low.removesuffix("s"), low.removesuffix("es"), low.removesuffix("ies") + "y"}
    return any(f in lx.PERSON_NOUNS for f in forms)


# Words before "till" that make it part of a noun phrase ("two till staff", "the till girl", "of till staff").
_BEFORE = frozenset("the a an two three four five six seven eight nine ten eleven twelve dozen few couple pair "
                    "trio several some many both our their his her its of and new young senior head other".split())


def with_till_workers(text: str) -> str:
    """The text with "till staff" written "till-staff" (see the module doc); "waits till people
    leave" keeps its time word."""
    def joined(m: re.Match[str]) -> str:
        before = m.string[:m.start()].split()[-1:]
        said = bool(before) and (before[0].lower() in _BEFORE or before[0].isdigit())
        return f"{m.group(1)}-{m.group(2)}" if said and _person_word(m.group(2)) else m.group(0)
    return _TILL_PERSON.sub(joined, text)
