"""Whose room "his office" or "her room" is when the clause is read for a group of several: "The
professor and three of her students troop from her office to ...", "the manager and two interns walk
from his office". The clause's words belong to the last group said, but "his" and "her" name one
person: the nearest single person said before it in its sentence, whose own room it is (the
professor's office, not the students'). "Their office" and a group of one keep the group's own kind.
"""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language.mention import Mention
from grove_tui.language.sentence import Sentence

_SINGULAR = frozenset({"his", "her"})


def _single(m: Mention) -> bool:
    return m.count is not None and m.count.value == 1 and m.relation is None


def clause_owner(s: Sentence, mentions: Sequence[Mention], k: int, span: tuple[int, int]) -> str:
    """The kind of person whose own rooms the clause of mention k (its words `span`) names."""
    m = mentions[k]
    if _single(m) or m.count is None:
        return m.label
    said = [i for i in range(max(span[0], m.last + 1), span[1]) if s.low[i] in _SINGULAR]
    if not said:
        return m.label
    sentence = s.w[m.first].sentence
    before = next((x for x in reversed(mentions[:k]) if s.w[x.first].sentence == sentence and _single(x)), None)
    return before.label if before is not None else m.label
