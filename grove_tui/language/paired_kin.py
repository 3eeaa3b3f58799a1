"""Two people named as the kind of one pair (round 56): "a father-and-daughter pair solder at the bench",
"a mother and son duo wait", "a husband-and-wife team runs the stall". The words of the two people
were read as one more person beside the pair. They are written joined ("father-daughter pair"), as
the reader already reads them, with the verb after one pair said for one ("a mother and daughter team
run the stall": the duo runs it), and a "team" or "partnership" named by two people is a duo: two ("a
husband-wife team", "two father-son teams": two each)."""

from __future__ import annotations

import re

from grove_tui.language import lexicon as lx
from grove_tui.language.tokens import lemma, third_person, verb_lemma

_PAIR = re.compile(r"\b([A-Za-z]+)(?:\s*-\s*and\s*-\s*|\s+and\s+|\s*&\s*|-)([A-Za-z]+)\s*-?\s*"
                   r"(pair|duo|couple|twosome|team|partnership)(s?)\b(?:(\s+)([a-z]+)\b"
                   r"(\s+(?:the|a|an|his|her|their|its|our|my|some|two|both)\b)?)?", re.IGNORECASE)
_TWO = frozenset({"team", "partnership"})


def as_paired_kin(text: str) -> str:
    """The text with "<person> and <person> <pair>" written "<person>-<person> <pair>" (module doc)."""
    return _PAIR.sub(_joined, text)


def _joined(m: re.Match[str]) -> str:
    first, second, kind, plural = m.group(1), m.group(2), m.group(3), m.group(4)
    if not all(_person(w) for w in (first, second)):
        return m.group(0)
    if kind.lower() in _TWO:
        kind = "duo"
    space, verb = m.group(5) or "", m.group(6) or ""
    if not plural and verb and not verb.endswith("s") and (m.group(7) or verb_lemma(third_person(verb)) == verb):
        verb = third_person(verb)  # "a mother and daughter team run/staff the stall": the duo runs it, as one pair
    return f"{first}-{second} {kind}{plural}{space}{verb}{m.group(7) or ''}"


def _person(word: str) -> bool:
    low = word.lower()
    return low in lx.KIN_NAMES or low in lx.PERSON_NOUNS or lemma(low) in lx.PERSON_NOUNS or low == "master"
