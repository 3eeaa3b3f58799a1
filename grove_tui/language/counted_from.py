"""A count with an article and no noun, then where its people are from (round 58): "the two from the
chess club argue ...", "those three from accounts queue ...", "all four from the choir wait ...". The
bare "three from sales" is written "three people from sales" (language/chat_fragments.py); with an
article before it the parser read "the two" as nobody and the group fell to a vague crowd. A number word
after "the", "those", "these" or "all (the)" and before "from" and a word counts people."""

from __future__ import annotations

import re

_NUMBER = (r"(?:two|three|four|five|six|seven|eight|nine|ten|eleven|twelve|thirteen|fourteen|fifteen|sixteen|"
           r"seventeen|eighteen|nineteen|twenty|thirty|forty|fifty)")
_COUNTED_FROM = re.compile(r"\b((?:the|those|these|all(?:\s+the)?)\s+" + _NUMBER + r")\s+(?=from\s+[A-Za-z])",
                           re.IGNORECASE)


def with_counted_from(text: str) -> str:
    """The text with "the two from X" written "the two people from X" (module doc)."""
    return _COUNTED_FROM.sub(lambda m: f"{m.group(1)} people ", text)
