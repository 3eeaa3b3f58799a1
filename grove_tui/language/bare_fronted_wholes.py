"""A fronted whole said with a bare number, and its part said by a word for a group of a size (round 43):
"Of nine potters at the wheels, a trio sneak off to the tea room", "Of twelve nurses on the ward, a
pair head to the cafeteria". The readers of a fronted whole's part "a trio", "a pair" (fronted_size_parts.py,
fronted_subsets.py) take a whole opened by "the", "those", "these" or "all"; with a bare number the whole
was lost and only the part was read. The whole is the same people with or without "the", so "the" is
written in before those readers run ("Of the nine potters ..., a trio ..."). Only a number right after
an opening "Of"/"Out of" whose phrase runs to a comma and a part "a/an <pair, couple, trio, ...>" is
read so; "Of course, two guards walk ..." is untouched."""

from __future__ import annotations

import re

from grove_tui.language import lexicon as lx

_NUMBER = r"(?:\d+|" + "|".join(sorted((w for w in lx.NUMBER_WORDS if w.isalpha()), key=len, reverse=True)) + \
    r")(?:-(?:one|two|three|four|five|six|seven|eight|nine))?"
_PARTS = r"(?:pair|couple|duo|twosome|trio|threesome|quartet|foursome|quintet|fivesome|sextet)"
_BARE = re.compile(r"(?:^|(?<=[.;!?:])\s+|(?<=,)\s+(?:and|but|then|so)\s+)((?:[Oo]ut )?[Oo]f)\s+"
                   rf"(?={_NUMBER}\s[^,.;!?]{{1,80}},\s+an?\s+{_PARTS}\b)")


def with_fronted_whole_articles(text: str) -> str:
    """The text with "the" written into a fronted whole said with a bare number (module doc)."""
    return _BARE.sub(lambda m: f"{m.group(0)}the ", text)
