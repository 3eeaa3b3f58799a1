"""A person placed by a fronted with-phrase (round 26): "With Nan at the stove, the twins slump on the
settee", "With two guards on the door, visitors queue at the ticket desk". The phrase sets a second
person somewhere, standing there, while the clause after it is about others; the reader lost a name
said there ("Nan") or gave the person the clause's verb ("two guards" queuing). The phrase is said as a
clause of its own before the sentence is read: "Nan is at the stove, and the twins slump ...".
Only a person (a person word or a capitalised name) and a place said with a determiner count: "with
coffee in hand", "with their kids in tow", "with the alarm on" are left alone."""

from __future__ import annotations

import re

from grove_tui.language import lexicon as lx
from grove_tui.language.tokens import lemma

_PREPOSITIONS = r"at|on|by|in|near|beside|behind|outside|inside|next to|in front of|over by|up at|down at"
_DETERMINERS = r"the|a|an|his|her|their|its|our|my|your"
_WITH = re.compile(
    r"(?:(?<=^)|(?<=[.!?;]\s))With\s+(?P<who>[A-Za-z][\w'’-]*(?:\s+[\w'’-]+){0,4}?)\s+"
    rf"(?P<prep>{_PREPOSITIONS})\s+(?P<place>(?:{_DETERMINERS})\s+[^,.;!?]{{1,40}}?),\s+(?P<rest>[a-zA-Z])")
_NUMBERS = lx.NUMBER_WORDS
_NOT_NAMES = frozenset("the a an his her their its our my your this that".split())


def _a_person(who: str) -> bool:
    words = who.split()
    last = words[-1]
    low = last.lower()
    if low in lx.PERSON_NOUNS or lemma(low) in lx.PERSON_NOUNS:
        return True
    if low in lx.ROBOT_WORDS:
        return False
    return len(words) <= 2 and last[0].isupper() and last[1:].islower() and words[0].lower() not in _NOT_NAMES and \
        low not in lx.STOPWORDS


def _plural(who: str) -> bool:
    words = who.lower().split()
    if "and" in words or "&" in words:
        return True
    if words[0] in _NUMBERS and words[0] not in ("one", "a", "an"):
        return True
    return words[-1] != lemma(words[-1]) or words[-1] in ("people", "twins", "staff", "police")


def as_placing_clause(text: str) -> str:
    """The text with a fronted "With PERSON at PLACE, ..." said as "PERSON is at PLACE, and ..."."""
    def say(m: re.Match[str]) -> str:
        who = m.group("who")
        if not _a_person(who):
            return m.group(0)
        who = who[0].upper() + who[1:]
        verb = "are" if _plural(who) else "is"
        return f"{who} {verb} {m.group('prep')} {m.group('place')}, and {m.group('rest')}"
    return _WITH.sub(say, text)
