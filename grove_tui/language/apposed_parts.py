"""Part of a counted group said between commas with what sets it apart, before the group's verb (round
71): "three residents, two in wheelchairs, gather in the activity room", "a dozen pupils, one on
crutches, walk to the hall". The bare count was read as people of its own beside the whole, so the
scene had the two on top of the three. Said as "two of them in wheelchairs" it is the part of the
whole the reader already knows ("subset_of"). Only a smaller number than the whole, a word of being
somewhere, on something or with something after it, and a comma and a word after that (the verb)."""

from __future__ import annotations

import re

from grove_tui.language import lexicon as lx

_WORDS = {**lx.UNITS, **lx.TENS, "a dozen": 12, "dozen": 12}
_NUMBER = r"(?:\d+|" + "|".join(sorted(_WORDS, key=len, reverse=True)) + r")"
_STATES = "in|on|with|using|pushing|holding|carrying|wearing|asleep|awake|still|already|limping|clutching"
_PART = re.compile(rf"(?<![\w'’-])({_NUMBER})(\s+(?:[a-z][\w'-]*\s+){{0,2}}[a-z][\w'-]*s),\s+({_NUMBER})\s+(?:people\s+)?"
                   rf"(?=(?:{_STATES})\b[^,.;:!?()]{{0,50}},\s+(?!(?:and|or|but|plus|while|as)\b)[a-z])", re.IGNORECASE)


def _value(word: str) -> int | None:
    low = word.lower()
    return int(low) if low.isdigit() else _WORDS.get(low)


def with_apposed_parts(text: str) -> str:
    """The text with "<N> <people>, <M> <state>, <verb>" said "<N> <people>, <M> of them <state>, <verb>"."""
    def said(m: re.Match[str]) -> str:
        whole, part = _value(m.group(1)), _value(m.group(3))
        if whole is None or part is None or not 0 < part < whole:
            return m.group(0)
        return f"{m.group(1)}{m.group(2)}, {m.group(3)} of them "
    return _PART.sub(said, text)
