"""A counted part of someone's people (round 26): "a trio of the accused's brothers perch on ...",
"a pair of the victim's sisters wait ...", "a couple of the bride's friends ...". The owner between
"of" and the people keeps the parser from reading the count and its people as one mention; the
owner is dropped for the parser ("a trio of brothers"), as it says whose they are, not how many.
"""

from __future__ import annotations

import re

from grove_tui.language import lexicon as lx
from grove_tui.language.tokens import lemma

_COUNTERS = lx.NUMBER_WORDS | lx.TOGETHER_COLLECTIVES | frozenset(lx.IMPLIED_RANGES) | \
    frozenset("few several some many most all both none".split())
_OWNED = re.compile(r"\b([A-Za-z]+)(\s+of)\s+(?:the|his|her|their|my|our|your)\s+(?:[A-Za-z-]+\s+){0,2}?"
                    r"[A-Za-z-]+(?:'s|s')\s+((?:[a-z-]+\s+)?)([a-z]+s)\b")


def without_partitive_owners(text: str) -> str:
    """The text with the owner of a counted part of people dropped (see the module doc)."""
    def drop(m: re.Match[str]) -> str:
        if m.group(1).lower() not in _COUNTERS or lemma(m.group(4).lower()) not in lx.PERSON_NOUNS:
            return m.group(0)
        return f"{m.group(1)}{m.group(2)} {m.group(3)}{m.group(4)}"
    return _OWNED.sub(drop, text)
