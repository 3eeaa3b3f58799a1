"""Members said as included, in an aside (round 44): "A family of seven, grandparents included, haul
their cases ...", "Twelve walkers, the guide included, set off", "a party of ten, kids and all, ...". The
aside only says who is among the group before it (as "including the grandparents" does), not a group
of its own; it was read as a second group walking with the first. Written as "including ..." before
the sentence is parsed, it is read as that already is (an aside of the group's own members)."""

from __future__ import annotations

import re

# ", grandparents included,", ", the guide included.", ", kids and all,": one to four words, then the
# word that says they are among the group, then a comma or the end of the sentence.
_INCLUDED = re.compile(r",\s+((?:[A-Za-z][\w'’-]*\s+){0,3}[A-Za-z][\w'’-]*)\s+(?:included|and\s+all)\s*(?=[,.;!?]|$)",
                       re.IGNORECASE)
_VERB_LIKE = re.compile(r"\b(?:is|are|was|were|be|been|has|have|had|get|gets|got)\b", re.IGNORECASE)


def _including(m: re.Match[str]) -> str:
    members = m.group(1)
    if _VERB_LIKE.search(members):
        return m.group(0)  # "..., all costs are included,": a clause, no members
    return f", including {members}"


def with_included_members(text: str) -> str:
    """The text with members said as included written as "including ..." (see the module doc)."""
    return _INCLUDED.sub(_including, text)
