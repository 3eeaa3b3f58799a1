"""Children named without a person noun (round 29): "Grandad leads the little one by the hand to the
bathroom", "a nurse walks the wee ones to the ward", "the Hendersons' youngest by the toy box scampers
off", "Mum takes her eldest to the loo". The reader found no person in "the little one" after a verb
of leading (the child was lost) and none in "the Hendersons' youngest" (a vague crowd was made up);
each names a child, and is written with the noun ("the little child", "the Hendersons' youngest child")
before the sentence is parsed."""

from __future__ import annotations

import re

from grove_tui.language import lexicon as lx

_OWNER = r"(?:the|[Hh]er|[Hh]is|[Tt]heir|[Oo]ur|[Mm]y|[Yy]our|[A-Z][a-z]+(?:'s|s'|’s|s’))"
# "our youngest", "my eldest", "our littlest": the one child of a family by its place among them
_ORDER = r"(?:youngest|eldest|oldest|littlest|smallest)"
_ONES = re.compile(r"\b(" + _OWNER + r"\s+(?:little|young|wee|tiny|small|baby|middle|" + _ORDER + r"))"
                   r"\s+(one|ones|'un|'uns)\b")
_MOST = re.compile(r"\b(" + _OWNER + r"\s+" + _ORDER + r")\b(?!\s+(?:one|ones|'un|'uns)\b)"
                   r"(?=\s*([^\s]+)|\s*$)")
# A family by its name in the plural, then its youngest or eldest ("the Hendersons' youngest"): the child
# is said as "the youngest Henderson child", a phrase the reader finds with no verb right after it.
_FAMILY_MOST = re.compile(r"\b([Tt]he)\s+([A-Z][a-z]+)s['’]\s+(youngest|eldest|oldest)\b(?!\s+(?:one|ones|'un|'uns)\b)"
                          r"(?=\s*([^\s]+)|\s*$)")
_AFTER = frozenset("by at in on near beside with to into from through across over round around towards toward and then is was has had , . ; ! ? : -- off out up down".split())


def with_little_ones(text: str) -> str:
    """The text with "the little one" written "the little child" and "the Hendersons' youngest" written
    "the Hendersons' youngest child" (see the module doc)."""
    text = _ONES.sub(lambda m: m.group(1) + (" children" if m.group(2).endswith("s") else " child"), text)
    text = _FAMILY_MOST.sub(lambda m: f"{m.group(1)} {m.group(3)} {m.group(2)} child" if _bare(m.group(4)) else m.group(0),
                            text)  # "the Hendersons' youngest by the toy box": "the youngest Henderson child"
    return _MOST.sub(lambda m: m.group(1) + " child" if _bare(m.group(2)) else m.group(0), text)


def _bare(nxt: str | None) -> bool:
    """Whether the word after "youngest" starts no noun of its own: a preposition, a link, a stop or a
    verb ("scampers", "walked")."""
    if nxt is None:
        return True
    word = nxt.lower().rstrip(",.;!?:")
    if nxt[0] in ",.;!?:" or word in _AFTER:
        return True
    if word in lx.PERSON_NOUNS or word.rstrip("s") in lx.PERSON_NOUNS or word == "of":
        return False
    return word.endswith(("s", "ed"))
