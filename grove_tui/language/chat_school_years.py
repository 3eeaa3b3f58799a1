"""School years said in chat as the pupils themselves (round 51): "12 yr7s in the hall + 2 teachers",
"Y9s wander round the shop", "the year 10s queue". With a verb the plural was read as people, but in a
list of fragments "yr7s" named nobody and its count went to the next group. A school year in the plural
is read as that year's pupils: "12 year 7 pupils in the hall"."""

from __future__ import annotations

import re

_YEARS = re.compile(r"\b(?:yrs?\s?|y|year\s?)(1[0-3]|[1-9])s\b", re.IGNORECASE)


def with_school_year_pupils(text: str) -> str:
    """The text with each plural school year ("yr7s", "Y9s", "year 10s") said as its pupils."""
    return _YEARS.sub(lambda m: f"year {m.group(1)} pupils", text)
