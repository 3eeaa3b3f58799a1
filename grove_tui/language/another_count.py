"""People said as more of a group before: "another nurse" is one more, "another 5" and "another five
porters" that many more (the small parser gives "another" no count of its own); "the other 6", "the
remaining four guests" are that many more of the group before, counted by the number after the
words of rest (without the number, "the other nurse" is read as before)."""

from __future__ import annotations

from grove_tui.language.counts import number_at
from grove_tui.language.model import Count
from grove_tui.language.people import People
from grove_tui.language.sentence import Sentence


_REST_WORDS = frozenset({"other", "remaining", "last", "final"})


def the_other_count(s: Sentence, at: int) -> bool:
    """Whether "the other N" or "the remaining N" starts at `at` ("Ten guests wait; the other 6 are
    in the bar"): N more people, where the parser's "the other" had left the number to nobody."""
    return (at + 2 < s.n and s.low[at] == "the" and s.low[at + 1] in _REST_WORDS
            and (num := number_at(s, at + 2)) is not None and num[0] >= 1)


def more_people(s: Sentence, people: People, at: int) -> tuple[int | None, int, Count]:
    """(person word or None, last word, count) of "another ..." at `at`: "another nurse" is one more,
    "another 5" or "another five porters" that many more."""
    num = number_at(s, at + 2 if the_other_count(s, at) else at + 1)
    if num is None or num[0] < 1:
        head = people.person_head(at + 1, counted=False)
        return head, head if head is not None else at, Count("exact", 1, 1, 1)
    head = people.person_head(num[1], counted=True)
    return head, head if head is not None else num[1] - 1, Count("exact", num[0], num[0], num[0])
