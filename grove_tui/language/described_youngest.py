"""A child named by "youngest" or "little one" with a describing word before it (round 32): "Nana steers
our drowsy youngest from the loo to his bedroom", "Dad carries his sleepy little one to the car", "the
twins' poorly eldest waits at reception". `little_ones.py` writes "our youngest" as "our youngest child";
with a word between the owner and "youngest" it did not, and the child moved or waiting was lost. Written
the same way, without the describing word the small parser mis-tags ("our youngest child"), and "the
sleepy little one" as "the sleepy little child", the child is one group like any other."""

from __future__ import annotations

import re

from grove_tui.language import lexicon as lx
from grove_tui.language.little_ones import _AFTER, _ORDER, _OWNER, _bare

_WORD = r"(?:[a-z][a-z-]+)"
_MOST = re.compile(r"\b(" + _OWNER + r"((?:\s+" + _WORD + r"){1,2})\s+" + _ORDER + r")\b"
                   r"(?!\s+(?:one|ones|'un|'uns)\b)(?=\s*([^\s]+)|\s*$)")
_ONES = re.compile(r"\b(" + _OWNER + r"((?:\s+" + _WORD + r"){1,2})\s+(?:little|young|wee|tiny|small|baby|middle|"
                   + _ORDER + r"))\s+(one|ones|'un|'uns)\b")


# "his drowsy little girl", "her poorly wee brother" (round 72): a describing word before "little" the parser
# takes for a noun, dropped so that the child is said ("his little girl").
_LITTLE_KIN = re.compile(r"\b(" + _OWNER + r")\s+(" + _WORD + r")\s+((?:little|wee|tiny|baby)\s+(?:girl|boy|son|"
                         r"daughter|sister|brother|grandson|granddaughter|niece|nephew|cousin)s?)\b")


def _describes(words: str) -> bool:
    """Whether the words between the owner and "youngest" only describe the child: no person, link or verb."""
    return all(w not in _AFTER and w not in lx.PERSON_NOUNS and w.rstrip("s") not in lx.PERSON_NOUNS
               and w not in ("youngest", "eldest", "oldest", "littlest", "smallest", "one", "a", "an", "the")
               for w in words.lower().split())


def with_described_youngest(text: str) -> str:
    """The text with "our drowsy youngest" written "our youngest child" (module doc)."""
    text = _LITTLE_KIN.sub(lambda m: f"{m.group(1)} {m.group(3)}" if _describes(m.group(2)) else m.group(0), text)
    text = _ONES.sub(lambda m: m.group(1) + (" children" if m.group(3).endswith("s") else " child")
                     if _describes(m.group(2)) else m.group(0), text)
    return _MOST.sub(lambda m: _without(m.group(1), m.group(2)) + " child"
                     if _describes(m.group(2)) and _bare(m.group(3)) else m.group(0), text)


def _without(phrase: str, words: str) -> str:
    """"our drowsy youngest" as "our youngest": the small parser takes many a describing word before a
    superlative for a noun ("drowsy") and splits the child's phrase there."""
    return phrase.replace(words, "", 1)
