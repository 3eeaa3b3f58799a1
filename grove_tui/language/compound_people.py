"""A person noun inside a chain of nouns that ends in another person noun ("two coach company reps",
"ten sports club coaches"): the chain names the kind of the last person, so the phrase is that person
and keeps its count, not a thing named after the first ("coach" of "coach company")."""

from __future__ import annotations

from grove_tui.language.sentence import Sentence


def chain_end(s: Sentence, k: int) -> int | None:
    """The last noun of a chain of two or more compound nouns starting at k, each modifying the
    next, else None ("coach company reps" from "coach": "reps"). A chain of one ("security guards")
    is left to the plain reading."""
    j = k
    while j < s.n and s.w[j].dep == "compound" and s.w[j].pos in ("NOUN", "PROPN") and s.w[j].head == j + 1:
        j += 1
    if j - k < 2 or j >= s.n or s.w[j].pos not in ("NOUN", "PROPN"):
        return None
    return j
