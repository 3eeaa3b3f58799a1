"""People said as more of a group before: "another nurse" is one more, "another 5" and "another five
porters" that many more (the small parser gives "another" no count of its own)."""

from __future__ import annotations

from grove_tui.language.counts import number_at
from grove_tui.language.model import Count
from grove_tui.language.people import People
from grove_tui.language.sentence import Sentence


def more_people(s: Sentence, people: People, at: int) -> tuple[int | None, int, Count]:
    """(person word or None, last word, count) of "another ..." at `at`: "another nurse" is one more,
    "another 5" or "another five porters" that many more."""
    num = number_at(s, at + 1)
    if num is None or num[0] < 1:
        head = people.person_head(at + 1, counted=False)
        return head, head if head is not None else at, Count("exact", 1, 1, 1)
    head = people.person_head(num[1], counted=True)
    return head, head if head is not None else num[1] - 1, Count("exact", num[0], num[0], num[0])
