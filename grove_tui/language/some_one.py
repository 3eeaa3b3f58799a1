""""Some" before one person, as chat says it ("some guy at the printer", "some woman shouting at the
robot"): one person, not a vague few. "Some" before a singular word for a person is read as "a"; before
a plural ("some guys"), a word for many ("some staff", "some family") or anything else it is left."""

from __future__ import annotations

import re

from grove_tui.language import lexicon as lx
from grove_tui.language.tokens import lemma

_SOME = re.compile(r"\b([Ss]ome)\s+([a-z]+)\b(?!\s+(?:of|or)\b)")
# Words for people that are also words for many: "some staff", "some police".
_MANY = frozenset("staff police people folk folks crew youth personnel security management admin clergy family "
                  "team class public company".split())


def some_one(text: str) -> str:
    """The text with "some" before one person written "a" (module doc)."""
    return _SOME.sub(_one, text)


def _one(m: re.Match[str]) -> str:
    word = m.group(2)
    if word not in lx.PERSON_NOUNS or lemma(word) != word or word in _MANY or word in lx.IMPLIED_RANGES:
        return m.group(0)
    article = "an" if word[0] in "aeiou" else "a"
    return f"{article.capitalize() if m.group(1)[0] == 'S' else article} {word}"
