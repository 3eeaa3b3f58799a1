"""A fronted "while" clause in the passive whose doer is said with "by" before the comma: "While the
pharmacy is restocked by a porter, two nurses wait in the lobby", "As the tills are emptied by a
cashier, a shopper waits at the bakery". The parser reads the doer and the people after the comma as
one list ("a porter, two nurses"), so the doer took the others' place. Said the other way round ("the
pharmacy is restocked by a porter while two nurses wait ..."), which the reader already reads, the doer
stays at the place worked on. Only a clause of "is/are (being) ...ed by" with its comma."""

from __future__ import annotations

import re

_FRONTED = re.compile(r"(^|[.!?;]\s+)(while|whilst|as|when)\s+((?:the|a|an|his|her|their|its|our)\s+[^,.;]+?\s+"
                      r"(?:is|are|was|were|gets|get)\s+(?:being\s+)?[a-z]+(?:ed|en|pt|wn)\s+by\s+"
                      r"(?:the|a|an|some|two|three|four|five|one|\d+)\s+[^,.;]+?),\s+(?=[a-z0-9])", re.IGNORECASE)


def with_fronted_passives_after(text: str) -> str:
    """The text with each such fronted passive clause said first as a main clause, "while" after
    it (see the module doc)."""
    def moved(m: re.Match[str]) -> str:
        clause = m.group(3)
        return f"{m.group(1)}{clause[:1].upper()}{clause[1:]} while "  # "as" after the clause reads as a cause

    return _FRONTED.sub(moved, text)
