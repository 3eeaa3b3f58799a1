"""A fronted feeling before the subject (round 26): "Fascinated, a little lad near the aquariums
toddles over to the robot", "Worried, an old man ...". The parser reads the capitalised first word
as a name; it says how the person feels, so it is written small for the parser ("fascinated, a
little lad ...") and no one is read from it. Round 48: a feeling that is no verb form ("Spellbound, a
wee lad ...", "Wary, an old man ...", "Agog, two boys ...") is one too: a word of the feeling lexicon or
an adjective shaped so ("awestruck", "nervous", "fearless", "joyful"). The parser reads even a small
"wary" as a name, so such a word is left out of the parsed text; the feeling is read from the prompt
as typed (feeling_adjectives.py).
"""

from __future__ import annotations

import re

from grove_tui.language.feeling_adjectives import FEELINGS
from grove_tui.language.parser import known_word

_FRONTED = re.compile(r"^([A-Z][a-z]{3,}(?:ed|ing)),\s+(?=(\w+))")
_FRONTED_WORD = re.compile(r"^([A-Z][a-z]{2,}),\s+(?=(\w+))")
# Endings of adjectives of feeling no name has ("awestruck", "spellbound", "nervous", "fearless", "joyful").
_FEELING_ENDINGS = ("struck", "bound", "ous", "less", "ful")
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
        m = _FRONTED_WORD.match(text)
        if m is None or m.group(2).lower() not in _SUBJECT_STARTS or not _feeling_word(m.group(1).lower()):
            return text
        rest = text[m.end():]  # the parser calls even "wary, an old man" a name: the feeling is left out
        return rest[:1].upper() + rest[1:]
    return m.group(1).lower() + text[m.end(1):]


def _feeling_word(word: str) -> bool:
    """Whether a word set before the subject says a feeling ("spellbound", "wary", "agog")."""
    return word in FEELINGS or (len(word) >= 6 and word.endswith(_FEELING_ENDINGS) and known_word(word)
                                and word not in _NAMES)
