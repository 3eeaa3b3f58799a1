"""A whole said first and its part after it, in two shapes the parts reader did not take (round 28):

- the whole with no person noun: "Of the nine sat in the waiting room, two ...", "Out of the twenty
  queuing at the bar, ...": the number is people ("Of the nine people sat in ...");
- the part said as a pair: "..., a pair get up and pay", "..., a couple head off": two of them
  ("a pair of them").

Both are written out before the sentence is parsed; the whole and its part are then read as any
"Of the twelve nurses on the ward, two go ..."."""

from __future__ import annotations

import re

from grove_tui.language import lexicon as lx

_NUMBER = r"(?:\d+|" + "|".join(sorted((w for w in lx.NUMBER_WORDS if w.isalpha()), key=len, reverse=True)) + \
    r")(?:-(?:one|two|three|four|five|six|seven|eight|nine))?"
_OPENING = r"(?:^|(?<=[.;!?:])\s+|(?<=,)\s+(?:and|but|then|so)\s+)"
_WHOLE = re.compile(_OPENING + r"((?:[Oo]ut )?[Oo]f (?:the|those|these|all)\s+(?:" + _NUMBER + r"))"
                    r"(?=\s+(?:sat|stood|sitting|standing|waiting|queuing|queueing|lined|seated|gathered|left|"
                    r"milling|lounging|in|at|on|by|near|inside|outside|around|round|who|that|here|there)\b)")
_PART = re.compile(r",\s+(an?\s+(?:pair|couple))\b(?!\s+of\b)")
_FRONTED = re.compile(_OPENING + r"(?:[Oo]ut )?[Oo]f (?:the|those|these|all)\s+[^,.;!?]{1,80},\s")


def with_fronted_subsets(text: str) -> str:
    """The text with a fronted whole's missing "people" and its part's "of them" written out (see the
    module doc)."""
    text = _WHOLE.sub(lambda m: m.group(0) + " people", text)
    out: list[str] = []
    at = 0
    for m in _FRONTED.finditer(text):
        comma = m.end() - 2
        part = _PART.match(text, comma)
        if part is None:
            continue
        out.append(text[at:part.end(1)] + " of them")
        at = part.end(1)
    out.append(text[at:])
    return "".join(out)
