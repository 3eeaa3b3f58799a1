"""A family said with its children after "with" ("a family with two kids walks to ..."): the children
are not the whole family, so it is the family, the children said and two parents the family implies
(count "implied": 2 kids -> 4), kept together; other collectives with people after "with" are those
people ("a tour ... with twelve tourists": the tourists, mentions.py)."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.mention import Mention
from grove_tui.language.model import Count

_PARENTS = 2  # the parents a family with children said implies


def with_members(before: Mention, members: Mention) -> tuple[Count | None, str]:
    """(count, label) of the collective `before` whose people `members` are, said after "with"."""
    count = members.count
    if before.collective != "family" or count is None or lx.OWNER_KINDS.get(members.label) != "child":
        return count, members.label
    value = count.value + _PARENTS
    return Count("implied", value, count.low + _PARENTS, count.high + _PARENTS, 1, value), before.label
