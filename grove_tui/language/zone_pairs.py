"""Everyone in two rooms: "everyone in the bar and the restaurant evacuates". A whole-zone group whose
place is followed by a second room in the same role, joined by "and", is everyone in each: the second
room's people are a group of their own, as many as that room holds."""

from __future__ import annotations

from dataclasses import replace
from typing import TYPE_CHECKING

from grove_tui.language.group_counts import settle_count

if TYPE_CHECKING:
    from grove_tui.language.clauses import Clause
    from grove_tui.language.mention import Mention
    from grove_tui.language.model import GroupReading
    from grove_tui.language.sentence import Sentence


def everyone_in_the_second_zone(s: Sentence, m: Mention, clause: Clause, g: GroupReading,
                                span: tuple[int, int], notes: list[str]) -> GroupReading | None:
    """The group of everyone in the second of two rooms said after a whole-zone mention ("everyone in
    the bar and the restaurant"), or None."""
    if not m.whole_zone or m.relation is not None or len(clause.places) < 2:
        return None
    first, second = clause.places[0], clause.places[1]
    if first.match is None or second.match is None or not second.sequel or second.prep != first.prep or \
            first.prep not in ("in", "inside", "at", "from", "of") or first.index != m.last + 1 or \
            not any(s.low[k] == "and" for k in range(first.end - 1, min(second.index + 1, s.n))):
        return None
    zone, other = first.match.zone, second.match.zone
    if zone == other:
        return None
    role = "start" if g.start == zone else "location" if g.location == zone else None
    if role is None:
        return None
    count = settle_count(s, m, span, other, [], notes)
    return replace(g, count=count, start=other) if role == "start" else replace(g, count=count, location=other)
