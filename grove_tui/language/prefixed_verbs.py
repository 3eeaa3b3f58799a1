"""Verbs written with a hyphened prefix, joined (round 44): "have two contractors re-cable the top of row
B", "a porter re-stocks the shelves", "two staff un-jam the tills". The parser splits "re-cable" into
"re", a hyphen and "cable", and a word after a hyphen is read as the end of a compound name
("check-in", "drop-off"), so the verb was lost and with it the place worked on. Written whole
("recable") the verb is one word, as the parser and the reader know such verbs."""

from __future__ import annotations

import re

_PREFIXED = re.compile(r"\b(re|un|de|pre)-(?=[a-z]{3,}\b)")


def with_joined_prefixes(text: str) -> str:
    """The text with "re-", "un-", "de-" and "pre-" joined to the word after them."""
    return _PREFIXED.sub(r"\1", text)
