"""Homophones typed in a hurry, read back before the parse (round 55): "two devs mosey form there desks
too the break room" means "from their desks to the break room", and the parser, given the slips, reads
no route at all. Each slip is read back only where the right word fits and the sentence lacks it:

- "form" as "from" and "too" as "to" right before a place phrase (a determiner or a possessive, then a
  word the world names places by, or that word itself, even misspelt: "form her ofice to the boardroom"), when the sentence has no other "from" / "to"
  and the word before is no one who could form something, and for "form" a "to" of the route follows
  ("extras form a line at X" is left as it is);
- "there" as "their" after a preposition and right before such a place word ("from there desks"),
  never before a verb or elsewhere ("wait there", "there are")."""

from __future__ import annotations

import re

from grove_tui.language import lexicon as lx
from grove_tui.language.misspelt_name_words import misspelt_name_word
from grove_tui.language.places import PlaceIndex
from grove_tui.language.tokens import lemma

_WORD = re.compile(r"[A-Za-z][A-Za-z'’-]*")
_LEADS = frozenset("a an the their there his her our my your its this that these those".split())
_PREPOSITIONS = frozenset("from form to too into in at by near past through towards toward round around".split())
_PRONOUNS = frozenset("they we you i he she who which that people others".split())
_SLIPS = {"form": "from", "too": "to"}


def _place_word(word: str, index: PlaceIndex) -> bool:
    """A word the world names places by, or such a word misspelt ("ofice" for "office": no English
    word, one edit from a name word), so "form her ofice to X" is still a route."""
    low = word.lower()
    return index.knows(low) or index.knows(lemma(low)) or misspelt_name_word(low, index)


def _place_phrase(words: list[str], j: int, index: PlaceIndex) -> bool:
    """Whether a place phrase starts at word j ("the break room", "there desks", "reception")."""
    if j < len(words) and words[j].lower() in _LEADS:
        j += 1
    return any(_place_word(words[k], index) for k in range(j, min(j + 3, len(words))))


def _route_on(lows: list[str], k: int) -> bool:
    """Whether a "to" of the route follows "form" ("form the cafe too the hall"); a line is formed at a place."""
    return any(w in ("to", "too", "into", "towards", "toward") for w in lows[k + 1:])


def _doer(word: str) -> bool:
    """Whether the word before "form" is who does it ("extras form a line", "they form a queue")."""
    return word in _PRONOUNS or lemma(word) in lx.PERSON_NOUNS or word in lx.NUMBER_WORDS or word.isdigit()


def with_homophone_slips(text: str, index: PlaceIndex) -> str:
    """The text with "form", "too" and "there" read back as "from", "to" and "their" where the sentence
    plainly means them (see the module doc)."""
    found = list(_WORD.finditer(text))
    words = [m.group(0) for m in found]
    lows = [w.lower() for w in words]
    out: list[tuple[int, int, str]] = []
    fixed: list[str] = list(lows)
    for k, low in enumerate(lows):
        right = _SLIPS.get(low)
        if right is not None and right not in lows and k > 0 and _place_phrase(words, k + 1, index) and \
                not _doer(lows[k - 1]) and (right == "to" or _route_on(lows, k)):
            out.append((found[k].start(), found[k].end(), right))
            fixed[k] = right
    for k, low in enumerate(lows):
        if low == "there" and 0 < k < len(words) - 1 and fixed[k - 1] in _PREPOSITIONS and \
                _place_word(words[k + 1], index):
            out.append((found[k].start(), found[k].end(), "their"))
    for start, end, word in sorted(out, reverse=True):
        text = text[:start] + word + text[end:]
    return text
