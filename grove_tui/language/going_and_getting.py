"""Going "and" getting something from a place ("eight go and fetch toast from the tea bar", "she nips and
buys a paper at the kiosk"): the "and" of everyday speech stands for "to", and the place the thing comes
from is where they go, for the thing. Said as "go to fetch toast from the tea bar", the going verb takes
the place as its destination and the errand as its purpose, as the reader already reads it."""

from __future__ import annotations

import re

from grove_tui.language import lexicon as lx

_GOING = r"(?:go|goes|going|went|nip|nips|nipping|nipped|pop|pops|popping|popped|dash|dashes|dashed|dashing)"
_IRREGULAR = {"got": "get", "bought": "buy", "took": "take"}


def _base(verb: str) -> str | None:
    """The base form of a verb of getting, or None when the word is no such verb."""
    low = verb.lower()
    for form in (low, _IRREGULAR.get(low, ""), low[:-2] if low.endswith("es") else "", low[:-1] if low.endswith("s") else "",
                 low[:-2] if low.endswith("ed") else "", low[:-3] if low.endswith("ped") or low.endswith("bed") else ""):
        if form and form in lx.TRANSACTION_VERBS - {"take"}:
            return form
    return None


_AND_GETTING = re.compile(rf"\b({_GOING})\s+and\s+([A-Za-z]+)\b", re.IGNORECASE)


def going_to_get(text: str) -> str:
    """The text with each "go and <get>" said "go to <get>" (module doc)."""
    def said(m: re.Match[str]) -> str:
        base = _base(m.group(2))
        return m.group(0) if base is None else f"{m.group(1)} to {base}"
    return _AND_GETTING.sub(said, text)
