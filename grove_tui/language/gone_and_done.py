"""Going and doing something in a place is going there (round 53): "three nine-year-olds go and flop
in the café seating", "two dads went and sat in the family room", "the twins go and hide behind the
stage". "Go and <verb> in X" says where the people go, though the second verb (a stay) would read X
as where they already are. The reader knows "go to X" well, so the phrase is said that way before the
sentence is read, in the going verb's own form ("went and sat in the" -> "went to the"). A wait or a
queue ("go and queue at the bar") is left as it is: the reader reads that stay where it is said.

Going "and" getting something from a place (round 55: "eight go and fetch toast from the tea bar", "she nips and
buys a paper at the kiosk") is said "go to fetch toast from the tea bar" early on (`going_to_get`): the going verb
then takes the place as its destination and the errand as its purpose, as the reader already reads it."""

from __future__ import annotations

import re

from grove_tui.language import lexicon as lx

_GONE_AND = re.compile(
    r"\b(?P<go>go|goes|went|going|gone)\s+and\s+(?P<verb>[a-z]+)(?:\s+(?:down|about|around|round|up|off))?"
    r"\s+(?:in|on|at|by|inside|near|beside|behind)\s+(?=(?:the|a|an|their|our|his|her|its|this|that|one)\b)",
    re.IGNORECASE)
_STAYS_SAID = frozenset("wait waits waited waiting queue queues queued queueing queuing line lines lined".split())


def as_gone_to(text: str) -> str:
    """The text with going and doing something in a place said as going to it (module doc)."""
    def say(m: re.Match[str]) -> str:
        if m.group("verb").lower() in _STAYS_SAID:
            return m.group(0)
        return f"{m.group('go')} to "
    return _GONE_AND.sub(say, text)

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
