"""Words between two people that leave them one subject: a participle of company before the second
("a defendant flanked by two guards walks to ...", "a child, followed by her dad, runs to ...") and
a "with" phrase describing the first ("a boy with a broken arm and his mum wait at ..."). The small
parser reads the participle as the first person's own verb and the "with" phrase as the end of the
first subject, so the main verb after the second person would be the second's only; both share it.
And people joined by "and" before those who move someone ("A doctor and two nurses wheel a patient
from ward A to radiology") go the moved person's way too (share_with_joined_movers).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import replace
from typing import TYPE_CHECKING

from grove_tui.language.people import People
from grove_tui.language.sentence import Sentence

if TYPE_CHECKING:
    from grove_tui.language.clauses import Clause
    from grove_tui.language.mention import Mention

# Participles saying who goes along with the person before them ("flanked by", "escorted by"): the
# people after "by" go the same way as that person.
COMPANY_PARTICIPLES = frozenset(
    "flanked accompanied escorted followed trailed tailed shadowed chaperoned shepherded "
    "guided led ushered supported helped joined surrounded pushed wheeled carried".split())
# Words that may end a "with" phrase about a person's state or belongings before "and".
_PHRASE_WORDS = frozenset({"a", "an", "the", "his", "her", "their", "its", "some", "two", "one", "no"})


def company_between(s: Sentence, first_last: int, second_first: int) -> bool:
    """Whether the words from just after one person to the next person are only a participle of
    company and "by", maybe set off by commas ("a defendant, flanked by two guards, ...")."""
    words = [s.low[i] for i in range(first_last + 1, second_first) if s.low[i] != ","]
    return len(words) == 2 and words[0] in COMPANY_PARTICIPLES and words[1] == "by"


def attribute_end(s: Sentence, people: People, person: int) -> int:
    """The last word of a "with" phrase right after the person word at `person` that says how they
    are or what they carry ("with a broken arm", "with his rucksack") and ends before "and" another
    person; `person` itself when there is none. A phrase naming a person ("with her son") is company,
    not an attribute, and keeps its own reading."""
    if person + 1 >= s.n or s.low[person + 1] != "with":
        return person
    k = person + 2
    while k < s.n and k < person + 7 and s.low[k] != "and":
        if s.is_punct(k) or people.is_person_noun(k) or s.w[k].tag in ("VBZ", "VBP", "VBD", "VB", "MD"):
            return person  # "with her son", or the clause's verb: no attribute
        if not (s.w[k].pos in ("NOUN", "ADJ", "PROPN", "NUM") or s.low[k] in _PHRASE_WORDS or s.w[k].tag == "VBN"):
            return person
        k += 1
    if k >= s.n or s.low[k] != "and" or k == person + 2:
        return person
    return k - 1


def share_with_joined_movers(s: Sentence, mentions: Sequence[Mention], clauses: list[Clause],
                             led_by: Callable[[int], bool]) -> None:
    """"A doctor and two nurses wheel a patient from ward A to radiology": the movers are given the
    route the moved person is said to take only after the first of them shared their clause without it
    (groups.py), so the doctor stood still; whoever is joined to the movers by "and" takes it too."""
    for k in range(len(mentions) - 3, -1, -1):
        words = [s.low[x] for x in range(mentions[k].last + 1, mentions[k + 1].first) if s.low[x] != ","]
        if words == ["and"] and led_by(mentions[k + 2].first) and not clauses[k].places and clauses[k + 1].places \
                and mentions[k + 1].relation is None and s.w[mentions[k].first].sentence == s.w[mentions[k + 2].first].sentence:
            clauses[k] = replace(clauses[k + 1])
