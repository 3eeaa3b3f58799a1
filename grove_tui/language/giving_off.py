"""Hazards said by a thing giving off smoke or sparks, or blowing (round 33): "when the panel saw starts
smoking", "as an oven starts to smoke", "a heater is sparking", "the fuse box sparks", "a gas main
ruptures", "a transformer blows", "the boiler blows up". The verb's subject is a thing (a noun that is
no person), so people who leave after it evacuate (`hazards.py`). A person who smokes ("a porter starts
smoking by the bins") is no hazard, nor is a whistle that blows."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.a_smoke import a_smoke_had
from grove_tui.language.sentence import Sentence

# Verbs of a thing giving off a hazard, every form ("smokes", "is smoking", "starts to smoke").
_GIVING_OFF = frozenset(f"{v}{end}" for v in ("smok", "ruptur") for end in ("e", "es", "ed", "ing")) | frozenset(
    f"{v}{end}" for v in ("smoulder", "smolder", "spark") for end in ("", "s", "ed", "ing")) | frozenset(
    "short-circuits short-circuited short-circuiting".split())
# Things that blow as a hazard ("a fuse blows", "the transformer blew"); any thing that "blows up".
_BLOWING_THINGS = frozenset("fuse fuses transformer transformers generator generators boiler boilers battery "
                            "batteries substation circuit circuits socket sockets tyre cylinder cylinders".split())
_BLOWS = frozenset("blow blows blew blowing blown".split())
# Words between the thing and its verb ("starts smoking", "is suddenly sparking", "begins to smoke").
_BETWEEN = frozenset("suddenly just then has have had is are was were starts start started begins begin began "
                     "to keeps keep".split())
# Kinds of word that are no thing's noun (the small parser may tag "saw" or "main" as a verb or adjective).
_NO_SUBJECT = frozenset("DET ADP PRON PUNCT ADV AUX CCONJ SCONJ PART NUM INTJ".split())
# Words that say the subject is a person, not a thing.
_PERSONS = frozenset("who he she they someone somebody everyone i we you".split())


def giving_off_cue(s: Sentence, i: int) -> bool:
    """Whether the word at i is a thing's verb of giving off smoke or sparks, or of blowing (module doc)."""
    w = s.low[i]
    blows = w in _BLOWS
    if w not in _GIVING_OFF and not blows or a_smoke_had(s, i):
        return False  # "for a quick smoke": a cigarette (a_smoke.py)
    if s.w[i].pos not in ("VERB", "NOUN", "AUX") or i == 0:
        return False
    if i + 1 < s.n and s.w[i + 1].pos in ("NOUN", "PROPN") and s.low[i + 1] not in lx.PERSON_NOUNS:
        return False  # "the outdoor smoking shelter", "a spark plug": a thing's name
    k = i - 1
    while k > 0 and s.low[k] in _BETWEEN:
        k -= 1
    if s.low[k] in _BETWEEN:
        return False
    k = _before_numbered_place(s, k)
    subject = s.low[k]
    if s.w[k].pos in _NO_SUBJECT or subject in _PERSONS or s.is_punct(k):
        return False
    if subject in lx.PERSON_NOUNS or s.lemma(k) in lx.PERSON_NOUNS or subject.rstrip("s") in lx.PERSON_NOUNS:
        return False
    if blows:
        up = i + 1 < s.n and s.low[i + 1] == "up"
        return up or subject in _BLOWING_THINGS
    return True


def _before_numbered_place(s: Sentence, k: int) -> int:
    """The thing before a numbered place the word at k ends ("a printer behind counter 3 starts smoking":
    the printer, not the number), or k itself (round 49)."""
    if s.w[k].pos != "NUM" or k < 3 or s.w[k - 1].pos not in ("NOUN", "PROPN"):
        return k
    for j in range(k - 2, max(k - 5, 0), -1):
        if s.w[j].pos == "ADP":
            return j - 1 if s.w[j - 1].pos in ("NOUN", "PROPN") else k
    return k
