"""Describing words listed with a comma before a person (round 42): "a pale, woozy student", "two
tired, hungry nurses", "a tall, bearded man". The small parser ends the person at the comma ("a
pale" is one person, "woozy student" another) or takes the word after it for a noun, so a helper's
object ("a nurse helps a pale, woozy student off the chairs") was lost. A comma between describing
words right before a person word says one person; the text is read without it."""

from __future__ import annotations

from grove_tui.language.lexicon import PERSON_NOUNS
from grove_tui.language.parser import Word, parse
from grove_tui.language.tokens import lemma

# Words that may open the person's phrase before the first describing word.
_OPENERS = frozenset("a an the his her their my our your its this that these those two three four five six "
                     "seven eight nine ten some several few".split())
# Endings of describing words the small parser calls nouns ("woozy", "tipsy", "bleary-eyed").
_DESCRIBING_ENDS = ("y", "ed", "ous", "ish", "ful", "less", "al", "ic", "ive", "ble", "ing", "ly")
# Describing words the small parser calls nouns, with no ending that says so ("a pale, shaky patient").
_PLAIN_DESCRIBING = frozenset("pale frail weak old young tall short thin stout small big lost sick ill drunk".split())
# Words that are never the describing words of a list ("the ward, two nurses", "the desk, and").
_NOT_DESCRIBING = frozenset("and or but then two three four five six seven eight nine ten some all both "
                            "only other another".split())


def _describing(w: Word) -> bool:
    low = w.lower
    if not low.replace("-", "").isalpha() or low in _NOT_DESCRIBING or low in _OPENERS:
        return False
    if w.pos == "ADJ" or low in _PLAIN_DESCRIBING:
        return True  # "elderly", a word for people too, describes one here
    if lemma(low) in PERSON_NOUNS or low in PERSON_NOUNS:
        return False
    return w.tag == "VBN" or low.endswith(_DESCRIBING_ENDS)


def _person(w: Word) -> bool:
    return w.lower in PERSON_NOUNS or lemma(w.lower) in PERSON_NOUNS


def without_adjective_commas(text: str) -> str:
    """The text with each comma between describing words right before a person word dropped."""
    if ", " not in text:
        return text
    words = parse(text)
    drop: list[int] = []
    for c, w in enumerate(words):
        if w.text != "," or c < 2 or c + 2 >= len(words):
            continue
        if words[c - 2].lower not in _OPENERS or not _describing(words[c - 1]):
            continue
        k = c + 1
        while k < len(words) and k < c + 3 and _describing(words[k]):
            k += 1
        if k == c + 1 or k >= len(words) or not _person(words[k]):
            continue
        drop.append(w.start)
    for start in reversed(drop):
        text = text[:start] + text[start + 1:]
    return text
