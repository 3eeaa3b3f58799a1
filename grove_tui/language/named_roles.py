"""A name with its role said after it (round 21): "Pete the butcher nips across ...", "Mr Jones the
manager walks ...". The parser makes the role an apposition of the name or, at the start of the
sentence, the name a verb, and the reader then found two people, took the role for a place of the
same name ("the butcher's"), or lost the subject's clause. The role says only who the named person
is, and the reader knows a role better than a first name it has no list of, so the name is left out
before the sentence is read: "The butcher nips across ...", one person.
A name is a capitalised word no list of the lexicon knows, followed by "the", a person word and a
verb said of one person ("nips", "walked")."""

from __future__ import annotations

import re

from grove_tui.language import lexicon as lx
from grove_tui.language.role_words import SHORT_ROLES
from grove_tui.language.tokens import lemma, verb_lemma

_TRADES = lx.AGENT_SUFFIXES + ("ent",)
_NAMED = re.compile(r"(?<![\w'’-])((?:[A-Z][a-z]{0,8}\.? )?)([A-Z][a-z]+) the ([a-z]+)(?= (\w+))")
# A role, then the name between commas, then a verb said of one ("the guide, Maria, leads ..."). ("Wilfred, a
# resident, shuffles ..." is read by language/people.py's fronted names.)
_ROLE_NAME = re.compile(r"(?<![\w'’-])((?:[Tt]he|[Oo]ur|[Mm]y|[Hh]is|[Hh]er|[Tt]heir|[Aa]n?) (?:[\w-]+ ){0,3})([a-z]+), "
                        r"((?:[A-Z][a-z]{0,8}\.? )?[A-Z][a-z]+(?: [A-Z][a-z]+)?), (?=(\w+))")
# Capitalised words that open a sentence before "the nurse ...", and are no names.
_NOT_NAMES = frozenset("then later meanwhile next now today tonight tomorrow yesterday afterwards soon first finally "
                       "again once still also suddenly eventually there here".split())


def _a_role(word: str) -> bool:
    return word in lx.PERSON_NOUNS or lemma(word) in lx.PERSON_NOUNS or word in SHORT_ROLES


def _a_trade(word: str) -> bool:
    """A role or a trade's word ("the butcher", "the fishmonger", "the florist")."""
    return _a_role(word) or (len(word) > 4 and word.endswith(_TRADES))


def _a_name(word: str) -> bool:
    low = word.lower()
    return not (low in lx.STOPWORDS or low in _NOT_NAMES or low in lx.LOCATION_ADVERBS or low.endswith("ly") or
                _a_role(low) or low in lx.TITLES or low in lx.SCENE_VERBS or low in lx.ROBOT_COMMAND_VERBS or
                low in lx.SENT_VERBS or low in lx.LEADING_VERBS)


def without_apposed_roles(text: str) -> str:
    """The text with a name said with its role after it read as the role ("Pete the butcher nips" ->
    "The butcher nips", "Mr Jones the manager walks" -> "The manager walks")."""
    def cut(m: re.Match[str]) -> str:
        before, name, role, after = m.group(1), m.group(2), m.group(3), m.group(4)
        said_of_one = after.endswith(("s", "ed")) and verb_lemma(after) != after
        if not (_a_name(name) and _a_trade(role) and said_of_one):
            return m.group(0)
        if before and before.strip(". ").lower() not in lx.TITLES:
            return f"{before}the {role}"  # "Then Pete the butcher nips": "Then the butcher nips"
        opening = m.start() == 0 or text[:m.start()].rstrip().endswith((".", "!", "?", ";"))
        return f"{'The' if opening else 'the'} {role}"
    return _ROLE_NAME.sub(_role_first, _NAMED.sub(cut, text))


def _said_of_one(verb: str) -> bool:
    return verb.endswith(("s", "ed")) and verb_lemma(verb) != verb


def _role_first(m: re.Match[str]) -> str:
    """"The guide, Maria, leads": "The guide leads" (the name between commas only says who the role is)."""
    words = m.group(3).split()
    if not (_a_trade(m.group(2)) and all(_a_name(w.rstrip(".")) or w.rstrip(".").lower() in lx.TITLES for w in words)
            and _said_of_one(m.group(4))):
        return m.group(0)
    return f"{m.group(1)}{m.group(2)} "
