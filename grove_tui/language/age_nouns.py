"""Ages said with a hyphen (round 19): "a dad and his 4-year-old walk to ...", "two 8-year-olds run
to ...", "two 8-year-old girls wait". The parser splits "4-year-old" into five words, so the age's
number is read as a count and the person after the hyphen loses the count before it ("two ...
girls" became a vague few), and said as a noun the person is lost. The reader has no age to keep,
so the age is read as what it says of the person: a child's ("young" before a person word, "child"
or "children" said alone), an adult's (nothing before a person word, "person" or "people" alone)."""

from __future__ import annotations

import re

from grove_tui.language import lexicon as lx
from grove_tui.language.tokens import lemma, verb_lemma

# "an eighty-year-old", "a twenty-one-year-old" (round 72): the tens written out, a unit maybe after them.
_TENS = {"twenty": 20, "thirty": 30, "forty": 40, "fifty": 50, "sixty": 60, "seventy": 70, "eighty": 80,
         "ninety": 90}
_TENS_SAID = r"(?:" + "|".join(_TENS) + r")(?:-(?:one|two|three|four|five|six|seven|eight|nine))?|"
_AGE = re.compile(r"\b(an?\s+)?(\d{1,3}|" + _TENS_SAID + "|".join(sorted(lx.UNITS, key=len, reverse=True)) +
                  r")[- ](year|yr|month|week)s?[- ]old(s?)\b(\W*)(\w*)", re.IGNORECASE)
_JOINING = frozenset({"and", "or", "but", "while", "with", "who", "as", "then", "both"})


def _noun_use(after: str, word: str) -> bool:
    """Whether the age is said as a noun: nothing after it but a verb or a small word."""
    low = word.lower()
    if not low or any(ch in after for ch in ",.;:!?()"):
        return True
    if lemma(low) in lx.PERSON_NOUNS or low in lx.PERSON_NOUNS:
        return False  # "a 4-year-old boy": the age of the person named
    return low in lx.DETERMINERS or low in lx.PLACE_PREPOSITIONS or low in _JOINING or low in lx.STOPWORDS or \
        verb_lemma(low) != low or low in lx.INTENT_VERBS or low in lx.HUMAN_SUBJECT_VERBS


def _unlisted_verb(plural: str, after: str, word: str) -> bool:
    """Whether the word after one age is its verb though no lexicon lists it ("our fourteen-year-old
    stumbles from ..."): one person's age, a space, then a word in -s that names no person (one person,
    then a plural noun, is not said)."""
    low = word.lower()
    return not plural and after == " " and len(low) > 3 and low.endswith("s") and not low.endswith("ss") and \
        low.isalpha() and not _person_word(word)


def _person_word(word: str) -> bool:
    """Whether a word names a person ("8-year-olds girls" is not said; "the 8-year-olds clamber" is a noun)."""
    low = word.lower()
    return lemma(low) in lx.PERSON_NOUNS or low in lx.PERSON_NOUNS


def _years(number: str) -> int:
    """The age a number word says ("eighty", "twenty-one", "seven")."""
    tens, _, unit = number.partition("-")
    return _TENS[tens] + lx.UNITS.get(unit, 0) if tens in _TENS else lx.UNITS[number]


def with_age_heads(text: str) -> str:
    """The text with each hyphenated age read as what it says of the person (see the module doc)."""
    def said(m: re.Match[str]) -> str:
        number = m.group(2).lower()
        years = int(number) if number.isdigit() else _years(number)
        child = years < 18 or m.group(3).lower() not in ("year", "yr")
        plural, after, word = m.group(4), m.group(5), m.group(6)
        if _noun_use(after, word) or (plural and "'" not in after and not _person_word(word)) or \
                _unlisted_verb(plural, after, word):
            person = ("children" if plural else "child") if child else ("people" if plural else "person")
        elif plural:
            return m.group(0)  # "the 8-year-olds' party": no person word after it
        else:
            person, after = ("young" if child else ""), (after if child else "")
        article = m.group(1) or ""
        if article.lower().startswith("an"):
            article = article[0] + article[2:]  # "an 8-year-old" -> "a child"
        return f"{article}{person}{after}{word}"
    return _AGE.sub(said, text)
