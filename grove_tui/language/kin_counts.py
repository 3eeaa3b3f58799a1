"""Counts said by kin words and by apposed strength, written out before the prompt is parsed
(round 18); the parser then reads them as it reads any count.

- "twin toddlers", "the twin girls": two of them ("two twin toddlers");
- "the dev team, five strong, troops out": a count in apposition ("the dev team, five people, ...");
- "triplets" are three, as "twins" are two (the lexicon's collectives).
"""

from __future__ import annotations

import re

from grove_tui.language import lexicon as lx
from grove_tui.language.tokens import lemma

_NUMBER = r"(?:\d+|" + "|".join(sorted((w for w in lx.NUMBER_WORDS if w.isalpha()), key=len, reverse=True)) + \
    r")(?:-(?:one|two|three|four|five|six|seven|eight|nine))?"
# "its audience, some 150 strong, pour out": a word of approximation before the number is kept.
_STRONG = re.compile(r",\s*((?:(?:some|about|around|roughly|nearly|almost|maybe|perhaps|approximately|over)\s+)?"
                     + _NUMBER + r")(?:-|\s+)strong\s*,", re.IGNORECASE)
_TWIN = re.compile(r"(?<![\w-])(twin)\s+([a-z]+s)\b", re.IGNORECASE)


def kin_counts(text: str) -> str:
    """The text with "twin <people>" and ", <n> strong," written as counts (see the module doc)."""
    text = _STRONG.sub(lambda m: f", {m.group(1)} people,", text)
    return _TWIN.sub(_twins, text)


def _twins(m: re.Match[str]) -> str:
    before = m.string[:m.start()].split()
    prev = before[-1].lower().strip(",.;:") if before else ""
    if lemma(m.group(2).lower()) not in lx.PERSON_NOUNS or prev.isdigit() or prev in lx.NUMBER_WORDS:
        return m.group(0)  # "twin beds", "two twin boys"
    if prev.endswith(("'s", "s'")):
        return f"two {m.group(2)}"  # "the defendant's twin brothers": his two brothers
    two = "Two" if m.group(1)[0].isupper() else "two"
    return f"{two} {m.group(1).lower() if two == 'Two' else m.group(1)} {m.group(2)}"
