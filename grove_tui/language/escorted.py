"""Words between two people that leave them one subject: a participle of company before the second
("a defendant flanked by two guards walks to ...", "a child, followed by her dad, runs to ...") and
a "with" phrase describing the first ("a boy with a broken arm and his mum wait at ..."). The small
parser reads the participle as the first person's own verb and the "with" phrase as the end of the
first subject, so the main verb after the second person would be the second's only; both share it.
"""

from __future__ import annotations

from grove_tui.language.people import People
from grove_tui.language.sentence import Sentence

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
