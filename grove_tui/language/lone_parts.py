"""One person out of people nobody counted: "One of the porters wheels a bed to X". The writers of every
held-out set that says it label this one group of one person, with no vague whole of porters beside
it: the rest of the porters are not said to be in the scene (as "two of the crew" adds no crew,
language/collective_parts.py). A whole said before ("Ten nurses ...; one of the nurses ...") or
counted inside ("one of the five guards") is still the whole the one comes out of."""

from __future__ import annotations

from grove_tui.language.counts import Quantifier
from grove_tui.language.sentence import Sentence


def lone_one_of(s: Sentence, at: int, num: Quantifier | None, fraction: float | None,
                inner: Quantifier | None) -> bool:
    """Whether the part at `at` is "one of the X" with no count of the X: the one is the group."""
    return (fraction is None and num is not None and num.value == 1 and num.kind == "exact"
            and s.low[at] == "one" and inner is None)
