"""Slips of a hurried keyboard the chat spelling lacks (issue 29), written out before parsing:

- small words typed with two letters swapped ("teh", "hte": the; "adn": and; "thier": their), which
  are no English word, so nothing else is lost by reading them back;
- a dropped "g" on a verb the lexicon does not know ("are muckin out", "were hosin down"): after a
  form of "be" and before a particle or a determiner, an "-in" word whose "i" follows a consonant is
  the "-ing" form ("are certain the ..." keeps its vowel before "in", and a noun never follows "are"
  with a particle after it; a capitalised name is kept: "are Robin out")."""

from __future__ import annotations

import re

# (Not "ot", "OT" being occupational therapy, nor "th", the "-th" of a date typed apart: "the 4 th".)
_SWAPPED = {"teh": "the", "hte": "the", "adn": "and", "nad": "and", "thier": "their", "taht": "that",
            "wiht": "with", "wtih": "with", "frmo": "from", "fomr": "from", "whiel": "while", "thne": "then",
            "waht": "what"}
_SWAPPED_WORD = re.compile(r"(?<![\w'/@&-])(" + "|".join(sorted(_SWAPPED, key=len, reverse=True)) + r")(?![\w'/@&-])",
                           re.IGNORECASE)
_BE = r"(?:are|is|was|were|am|be|been)"
_DROPPED_AFTER_BE = re.compile(r"(?<=\s)(" + _BE + r"\s+)([A-Za-z]*[b-df-hj-np-tv-z]in)(?:'|’)?"
                               r"(?=\s+(?:out|up|off|down|about|around|away|over|back|the|a|an|their|his|her|some)\b)",
                               re.IGNORECASE)


def written_out(text: str) -> str:
    """The text with swapped small words and dropped "g"s of unknown verbs written out (module doc)."""
    text = _SWAPPED_WORD.sub(lambda m: _cased(m.group(1), _SWAPPED[m.group(1).lower()]), text)
    return _DROPPED_AFTER_BE.sub(lambda m: m.group(1) + m.group(2) + "g" if len(m.group(2)) >= 4 and m.group(2)[0].islower()
                                   else m.group(0), text)


def _cased(typed: str, word: str) -> str:
    return word.capitalize() if typed[:1].isupper() else word
