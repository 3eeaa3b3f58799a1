"""First names joined as one subject (twenty-third session): "Alice and Bob walk to the kitchen", "Priya,
Tom and Alice chat in the kitchen", "Sam and Alice from accounts head to X". A lone name is a person by
its verb ("Alice walks"); in a list only the last name stands before the verb, and a name no list of
the lexicon knows was no one, so the whole list fell back to a vague crowd. A capitalised word the
parser calls a proper noun, in a list of two or more such names or person words joined by commas and
"and", the list followed by its verb or a phrase about the people, is one person each."""

from __future__ import annotations

from typing import TYPE_CHECKING

from grove_tui.language import lexicon as lx
from grove_tui.language.tokens import verb_lemma

if TYPE_CHECKING:
    from grove_tui.language.sentence import Sentence

_JOINS = frozenset({",", "and", "&"})
_AFTER_THE_LIST = frozenset({"VERB", "AUX", "ADP"})  # "walk", "are", "from accounts"


def _name(s: Sentence, k: int) -> bool:
    """Whether word k looks like a first name: a capitalised proper noun no place or list claims."""
    text = s.w[k].text
    if s.w[k].pos != "PROPN" or not text.isalpha() or len(text) < 2 or not text[:1].isupper() or \
            not text[1:].islower():
        return False
    low = s.low[k]
    return low not in lx.NON_PEOPLE and low not in lx.ROBOT_WORDS and not s.index.knows(s.lemma(k))


def _member(s: Sentence, k: int) -> bool:
    return _name(s, k) or s.low[k] in lx.KIN_NAMES or s.lemma(k) in lx.PERSON_NOUNS


def _list_around(s: Sentence, i: int) -> tuple[int, int] | None:
    """The first and last word of the list of single-word members word i is in, joined by commas and
    "and" (one word each), or None when i is in no list of two or more."""
    first = i
    while first >= 2 and s.low[first - 1] in _JOINS and _member(s, first - 2):
        first -= 2
    last = i
    while last + 2 < s.n and s.low[last + 1] in _JOINS and _member(s, last + 2):
        last += 2
    if first == last or "and" not in s.low[first:last + 1] and "&" not in s.low[first:last + 1]:
        return None
    return first, last


def joined_first_name(s: Sentence, i: int) -> bool:
    """Whether word i is a first name in a list of people said as one subject (module doc)."""
    if not _name(s, i):
        return False
    span = _list_around(s, i)
    if span is None:
        return False
    first, last = span
    if first > 0 and not (s.is_punct(first - 1) or s.w[first - 1].pos in ("SCONJ", "CCONJ", "ADV")):
        return False  # "... from Marks and Spencer": the list is no subject
    if last + 1 >= s.n:
        return False
    after = s.low[last + 1]  # the list's verb, which the parser may take for a noun ("Marek and Joanna stroll")
    return s.w[last + 1].pos in _AFTER_THE_LIST or after in lx.INTENT_VERBS or verb_lemma(after) in lx.INTENT_VERBS
