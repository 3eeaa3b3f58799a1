"""People said by a word the parser breaks apart: a relative by marriage ("my sister-in-law", "two
brothers-in-law") and a school year's pupils ("thirty Year 5s", "the Year-10s", "thirty Year Sixes"). The tokenizer splits them
at their hyphens or digits and the parser then loses the person, often with the whole clause ("My
sister-in-law reads in the bedroom" named nobody). Before parsing, the relative is said by the kin word
("my sister"), one person as before, and the year's pupils as "Year 5 pupils", the form already read. Round
69: a person still to become one ("a groom-to-be", "two brides-to-be", "a mum-to-be") is said by the noun
("a groom"): split, "to be" was read as a verb and the person lost their clause."""

from __future__ import annotations

import re

# "sister-in-law", "brothers-in-law", "mother in law": the kin word, in its number.
_IN_LAW = re.compile(r"\b(mothers?|fathers?|sisters?|brothers?|sons?|daughters?)\s*-\s*in\s*-\s*laws?\b"
                     r"|\b(mothers?|fathers?|sisters?|brothers?|sons?|daughters?)\s+in\s+law\b", re.IGNORECASE)
# "Year 5s", "year-10s": the pupils of that school year (not "Year 5 pupils", already read).
_TO_BE = re.compile(r"\b(?!(?:soon|yet|about|still|due|never)\b)([A-Za-z]{2,})\s*-\s*to\s*-\s*be\b", re.IGNORECASE)
_YEAR_PUPILS = re.compile(r"\b(year)\s*-?\s*(\d{1,2})s\b", re.IGNORECASE)
# "Year Sixes", "year tens" (round 48): the year said in words, its pupils read the same; not a count
# multiplied ("thirty Year Sixes" are thirty pupils, not thirty times six).
_YEAR_WORDS = {"ones": 1, "twos": 2, "threes": 3, "fours": 4, "fives": 5, "sixes": 6, "sevens": 7, "eights": 8,
               "nines": 9, "tens": 10, "elevens": 11, "twelves": 12, "thirteens": 13}
_YEAR_WORD_PUPILS = re.compile(r"\b(year)\s*-?\s*(" + "|".join(_YEAR_WORDS) + r")\b", re.IGNORECASE)


def with_whole_person_words(text: str) -> str:
    """The text with relatives by marriage said by their kin word and a school year's pupils as
    "Year N pupils" (see the module doc)."""
    text = _TO_BE.sub(r"\1", _IN_LAW.sub(lambda m: m.group(1) or m.group(2), text))
    text = _YEAR_WORD_PUPILS.sub(lambda m: f"{m.group(1)} {_YEAR_WORDS[m.group(2).lower()]} pupils", text)
    return _YEAR_PUPILS.sub(lambda m: f"{m.group(1)} {m.group(2)} pupils", text)
