"""A group said whole, then split by bare counts that add up to it: "Ten nurses: four on ward A, six
on ward B", "Place 5 guards, two at the main entrance and three at the pharmacy", "There are 12
visitors, 8 in the cafeteria and 4 in the waiting room". The parts are the whole's people, not more
of them: each is made a subset of the whole (`subset_of`), so the whole keeps nobody of its own
(`model.effective_counts`) and the scene has ten nurses, not twenty. A whole said with a place
of its own ("Ten nurses walk to ward A, four walk to ward B and six to ward C") is a group of its own.
A whole said with no number ("Shoppers: 20 in the food court, 10 in the supermarket") is as many as
its parts."""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import replace

from grove_tui.language import lexicon as lx
from grove_tui.language.model import Count, GroupReading

_NUMBER = re.compile(r"^\d+$")


def parts_of_a_split_whole(read: Sequence[GroupReading]) -> tuple[GroupReading, ...]:
    """The groups, with the bare counts right after a whole that add up to it made its subsets."""
    out = list(read)
    k = 0
    while k < len(out):
        whole = out[k]
        parts: list[int] = []
        j = k + 1
        while j < len(out) and out[j].relation is None and out[j].label == whole.label and _bare_count(out[j].who):
            parts.append(j)
            j += 1
        total = sum(out[p].count.value for p in parts)
        said_bare = whole.count.kind == "vague" and not any(_bare_count(w) for w in whole.who.split())
        if whole.relation is None and not (whole.start or whole.destination or whole.location or whole.via) and \
                (whole.count.kind in ("exact", "structured") and total == whole.count.value or said_bare) and \
                len(parts) >= 2 and all(out[p].count.kind == "exact" for p in parts):
            if said_bare:  # "Shoppers: 20 in the food court, 10 in the supermarket": as many as the parts
                out[k] = replace(whole, count=Count("exact", total, total, total), confidence=tuple(
                    c for c in whole.confidence if c.field != "count"))
            for p in parts:
                out[p] = replace(out[p], relation=f"subset_of:{k}")
            k = j
        else:
            k += 1
    return tuple(out)


def _bare_count(who: str) -> bool:
    """Whether the words of a group are a count and nothing else ("four", "2", "twenty five")."""
    words = who.lower().replace("-", " ").split()
    return bool(words) and all(_NUMBER.match(w) or w in lx.NUMBER_WORDS for w in words)
