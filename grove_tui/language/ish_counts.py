"""Rough numbers said with "-ish" ("200-ish spectators", "30ish", "fortyish fans", "a hundred-ish
runners"): about so many. Written before parsing as "about N", or as "N or so" after a determiner
("the 200-ish spectators" is "the 200 or so spectators"), because the parser takes "the about 200" as
no count at all and the group fell back to a vague few. "A hundred-ish" keeps its article inside the
number ("about a hundred"), never "a about hundred"."""

from __future__ import annotations

import re

# A number written in words takes "-ish" too ("forty-ish fans", "twelveish"): the words of tens and
# teens only, so no other word ending "-ish" (a "tallish" man) is read as a count.
_NUMBER_WORD = r"(?:twenty|thirty|forty|fifty|sixty|seventy|eighty|ninety|hundred|ten|eleven|twelve|[a-z]+teen)"
_DETERMINERS = r"(?:the|those|these|their|our|its|his|her|my|your|all|some)"
# "30-ish visitors", "20ish ppl", "a hundred-ish runners", "the fortyish fans": about so many
_ISH = re.compile(r"\b(?:(" + _DETERMINERS + r")\s+)?((?:a|one)\s+(?=hundred|thousand))?"
                  r"(\d+|" + _NUMBER_WORD + r"|thousand|(?:one|two|three|four|five|six|seven|eight|nine)(?=-))"
                  r"\s*-?\s*ish\b", re.IGNORECASE)


def _rough(m: re.Match[str]) -> str:
    determiner, article, number = m.group(1), m.group(2), m.group(3).lower()
    spoken = f"{article.strip().lower()} {number}" if article else number
    if determiner:
        return f"{determiner} {spoken} or so"
    return f"about {spoken}"


def ish_counts(text: str) -> str:
    """The text with each "-ish" count written as a rough number the parser reads as one."""
    return _ISH.sub(_rough, text)
