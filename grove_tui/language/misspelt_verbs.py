"""Misspelt verbs of going, written out before the prompt is parsed (round 54): "thirty infants from the
village school trapse across to the goats" ("traipse"), "two porters hurrys to ward B". Left as written,
the misspelt verb is tagged a noun and read as the last word of the place before it ("the village school
trapse"), a place the world lacks, so the prompt was refused.

A word is written out only when it is no English word the parser knows, no place word of the world and
no word for people (nor one edit from one, or from a place word's plural: those are put right by spelling.py and the people rule), and
exactly one verb of going or staying the lexicon knows has a form (base, "-s", "-ed", "-ing") one edit
away. Words of fewer than five letters and capitalised words (names) are left as written."""

from __future__ import annotations

import re
from functools import lru_cache

from grove_tui.language import lexicon as lx
from grove_tui.language.manner_walks import MANNER_WALKS
from grove_tui.language.parser import dictionary_word, known_word
from grove_tui.language.places import PlaceIndex
from grove_tui.language.spelling import near_person_noun, one_edit

_WORD = re.compile(r"(?<![\w'’-])([a-z]{5,})(?![\w'’-])")


@lru_cache(maxsize=1)
def _verb_forms() -> dict[int, dict[str, str]]:
    """Length -> {written form: verb}, for the verbs of going and staying the lexicon knows."""
    verbs = {v for v in (*lx.INTENT_VERBS, *MANNER_WALKS.split()) if v.isalpha() and len(v) >= 4}
    forms: dict[int, dict[str, str]] = {}
    for v in verbs:
        stem = v[:-1] if v.endswith("e") else v
        cy = v.endswith("y") and v[-2] not in "aeiou"  # "hurry": "hurries", "hurried"
        third = v[:-1] + "ies" if cy else v + ("es" if v.endswith(("s", "sh", "ch", "x")) else "s")
        past = v + "d" if v.endswith("e") else (v[:-1] + "ied" if cy else v + "ed")
        for form in (v, third, past, stem + "ing"):
            forms.setdefault(len(form), {}).setdefault(form, v)
    return forms


def _near_verb(word: str) -> str | None:
    """The one form of a verb of going one edit from `word`, or None when none or several are."""
    forms = _verb_forms()
    found = {form for n in (len(word) - 1, len(word), len(word) + 1)
             for form in forms.get(n, {}) if one_edit(word, form)}
    return found.pop() if len(found) == 1 else None


def _inflected_word(word: str) -> bool:
    """Whether `word` is a form of a real word, or one of the verb forms themselves ("strolls", "spilt")."""
    if any(word in forms for forms in _verb_forms().values()):
        return True
    for end in ("s", "es", "ed", "d", "ing", "t", "ies", "ied"):
        if word.endswith(end) and len(word) - len(end) >= 3:
            base = word[:-len(end)]
            if any(dictionary_word(b) or known_word(b) for b in (base, base + "e", base + "y", base + "l")):
                return True
    return False


def with_misspelt_verbs(text: str, index: PlaceIndex) -> str:
    """`text` with misspelt verbs of going written out (see the module doc)."""
    def fix(m: re.Match[str]) -> str:
        word = m.group(1)
        if known_word(word) or dictionary_word(word) or word in index.vocabulary or word in lx.PERSON_NOUNS \
                or near_person_noun(word) is not None or any(one_edit(word, t) or one_edit(word, t + "s") for t in index.name_words):
            return word
        if _inflected_word(word):
            return word  # "strolls", "spilt", "loiters": a real word the vocabulary holds only in its base form
        return _near_verb(word) or word
    return _WORD.sub(fix, text)
