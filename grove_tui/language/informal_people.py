"""Informal words for children and adults (round 62): "seven nippers clamber out of the sandpit", "a
handful of sprogs", "three bairns", "two grown-ups and four rugrats", "five geezers". The lexicon knew
none of these as people, so a counted number of them was read as a vague crowd of anyone; each is
written as the plain word it stands for ("kids", "adults", "men") before the prompt is parsed."""

from __future__ import annotations

import re

# Words for children and for grown-ups, singular and plural, by the plain word they stand for.
_ALWAYS: dict[str, str] = {}
for _plain, _words in {
    "kid": "nipper sprog tyke bairn wean rugrat ankle-biter ankle biter kiddie kiddy littlun littl'un little'un "
           "young'un youngun brat urchin scamp",
    "adult": "grown-up grownup",
    "man": "geezer codger",
    "person": "bod",
}.items():
    for _w in re.split(r"\s(?=[a-z])(?!biter)", _words):
        _ALWAYS[_w] = _plain
_PLURALS = {"kid": "kids", "adult": "adults", "man": "men", "person": "people"}
_WORD = re.compile(r"(?<![\w'-])(" + "|".join(re.escape(w) for w in sorted(_ALWAYS, key=len, reverse=True))
                   + r")(s|es)?(?![\w'-])", re.IGNORECASE)


def plain_people(text: str) -> str:
    """The text with informal words for people written plainly (see the module doc)."""
    return _WORD.sub(_plain_word, text)


def _plain_word(m: re.Match[str]) -> str:
    plain = _ALWAYS[m.group(1).lower()]
    word = _PLURALS[plain] if m.group(2) else plain
    return word[:1].upper() + word[1:] if m.group(1)[:1].isupper() else word
