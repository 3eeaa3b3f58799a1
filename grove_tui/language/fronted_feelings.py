"""A fronted feeling before the subject (round 26): "Fascinated, a little lad near the aquariums
toddles over to the robot", "Worried, an old man ...". The parser reads the capitalised first word
as a name; it says how the person feels, so it is written small for the parser ("fascinated, a
little lad ...") and no one is read from it.
"""

from __future__ import annotations

import re

from grove_tui.language.parser import known_word

_FRONTED = re.compile(r"^([A-Z][a-z]{3,}(?:ed|ing)),\s+(?=(\w+))")
_SUBJECT_STARTS = frozenset("a an the two three four five six seven eight nine ten some several his her their "
                            "our my this that these those one".split())

# Names that end as a verb form does and are in the parser's vocabulary.
_NAMES = frozenset("fred ted ned manfred wilfred alfred winifred mildred sigfried siegfried sterling browning "
                   "channing manning fleming harding golding cushing irving ewing deming reading king".split())


def _verb_form(word: str) -> bool:
    """Whether a word ending in -ed or -ing is a form of a real verb ("fascinated" of "fascinate",
    "worried" of "worry"), not a name that ends so ("Wilfred", "Sterling")."""
    stems: tuple[str, ...]
    if word.endswith("ing"):
        stems = (word[:-3], word[:-3] + "e", word[:-4])
    else:
        stems = (word[:-1], word[:-2], word[:-3] + "y", word[:-3])
    if word in _NAMES or not known_word(word):
        return False
    return len(word) >= 8 or any(len(stem) >= 3 and known_word(stem) for stem in stems)


def with_small_fronted_feelings(text: str) -> str:
    """The text with a fronted feeling before its subject's determiner written small."""
    m = _FRONTED.match(text)
    if m is None or m.group(2).lower() not in _SUBJECT_STARTS or not _verb_form(m.group(1).lower()):
        return text
    return m.group(1).lower() + text[m.end(1):]
