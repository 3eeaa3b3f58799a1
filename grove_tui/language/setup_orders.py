"""An order that sets people up rather than places them (issue 29): "Set up a yoga class of fifteen in the
hall and a pair of volunteers in the kitchen", "Arrange a choir of twelve in the lobby", "Lay on six
stewards at the gate". The reader knows "have" and "put" as such orders but not these, and so reads the
people after them as things set up. Written before parsing as "Have ...", which lists the groups joined
by "and" as any "Have ten nurses on the ward and two porters in the canteen"."""

from __future__ import annotations

import re

from grove_tui.language import lexicon as lx

_NUMBER = "|".join(sorted((w for w in lx.NUMBER_WORDS if w.isalpha()), key=len, reverse=True))
_ORDER = re.compile(r"(^|[.!?;]\s+)(?:[Ss]et up|[Ss]et out|[Pp]lace|[Pp]osition|[Ss]tation|[Ll]ay on|[Aa]rrange|[Oo]rgani[sz]e|[Ss]tage)\s+"
                    r"(?=(?:a|an|some|several|\d+|" + _NUMBER + r")\b)")


def as_setup_orders(text: str) -> str:
    """The text with an opening "Set up", "Arrange", "Lay on" ... said as "Have" (module doc)."""
    return _ORDER.sub(lambda m: m.group(1) + "Have ", text)
