"""Everyone a purpose treats ("pops into the pantry to make everyone a brew", "nips out to buy
everybody a coffee", "to get us all some cake") is whom the thing is for, not a group of people in the
scene: written before parsing without them ("to make a brew"), so the purpose keeps its thing and
no whole-zone crowd of "everyone" is read. Only right after "to" and a giving verb, and before the
thing's own article or "some"."""

from __future__ import annotations

import re

_GIVING = r"(?:make|makes|get|fetch|buy|pour|brew|grab|bring|cook|order|rustle\s+up|knock\s+up|sort)"
_TREATED = re.compile(r"\b(to\s+" + _GIVING + r")\s+(?:everyone|everybody|us\s+all|them\s+all|all\s+of\s+us"
                      r"|all\s+of\s+them)\s+(?=(?:a|an|some|the|their|our)\b)", re.IGNORECASE)


def without_treated_everyone(text: str) -> str:
    """The text without "everyone" as whom a purpose's thing is for (module doc)."""
    return _TREATED.sub(lambda m: m.group(1) + " ", text)
