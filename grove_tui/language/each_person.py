"""People each of a group takes along or has with them: "four nurses each escort a patient", "two
porters, each pushing a patient in a wheelchair", "three guides, each with a group of ten visitors".
The taken are as many per leader as said, so as many in all as the leaders times that: four patients,
two patients, three groups of ten visitors."""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language.mention import Mention
from grove_tui.language.model import Count
from grove_tui.language.people import People
from grove_tui.language.sentence import Sentence
from grove_tui.language.sequences import each_leader


def taken_by_each(s: Sentence, people: People, mentions: Sequence[Mention]) -> None:
    """Multiplies the count of people said right after "<leaders> (,) each <verb|with>" by the
    leaders' exact count (in place)."""
    for k in range(1, len(mentions)):
        leaders, m = mentions[k - 1], mentions[k]
        if m.count is None or leaders.count is None or leaders.count.kind != "exact" or leaders.count.value < 2:
            continue
        each = next((j for j in range(leaders.last + 1, m.first) if s.low[j] == "each"), None)
        if each is None or each + 2 < m.first - 1 or each_leader(s, people, each) != leaders.last:
            continue  # "each" right before the verb or "with" that takes them: "each escort a patient"
        n, c = leaders.count.value, m.count
        m.count = Count("exact", n, n, n) if c.value == 1 and c.high == 1 else \
            Count("structured", n * c.value, n * c.low, n * c.high, parties=n, party_size=c.value)
