"""A person named by what they lead with the noun "lead" (round 66): "the admin lead hurries to the
pantry", "the team lead walks from reception", "a site lead waits at the gate". The lexicon knows
"leader", not the office's noun "lead", and the small parser reads "lead" as the verb of "the
team" (a team of several) or as nobody. Said after a determiner and one word, and before a verb of
its own ("walks", "hurried", "is") or the end of the clause, it is written "leader": one person.
"The team lead visitors to the hall" (a plural verb and its object) is left alone."""

from __future__ import annotations

import re

from grove_tui.language import lexicon as lx
from grove_tui.language.tokens import lemma, verb_lemma

_ROLE = re.compile(r"\b(the|a|an|our|their|his|her|my|your|this|that|its)\s+([a-z][a-z-]+)\s+lead\b"
                   r"(?=\s*([,.;:!?)]|$|\s+([a-z']+)))", re.IGNORECASE)
_OWN_VERBS = frozenset("is was has had will would can could must should may might then who".split())
_NOT_MODIFIERS = frozenset("to will would can could must should may might and or but not also then".split())


def _verb_of_its_own(word: str) -> bool:
    """Whether `word`, after "the X lead", is the lead's own verb ("walks", "hurried", "is")."""
    if word in _OWN_VERBS:
        return True
    if lemma(word) in lx.PERSON_NOUNS or word in lx.PERSON_NOUNS:
        return False  # "the team lead kids to the hall": the team leads them
    return (word.endswith("s") or word.endswith("ed")) and verb_lemma(word) != word


def with_role_leads(text: str) -> str:
    """The text with "the admin lead" written "the admin leader" (see the module doc)."""
    def leader(m: re.Match[str]) -> str:
        modifier = m.group(2).lower()
        if modifier in _NOT_MODIFIERS or (modifier not in lx.IMPLIED_RANGES and (
                modifier in lx.PERSON_NOUNS or lemma(modifier) in lx.PERSON_NOUNS)):
            return m.group(0)  # "the guides lead ...": their verb; "the team lead walks": a team's leader
        after = m.group(4)
        if after is not None and not _verb_of_its_own(after.lower()):
            return m.group(0)
        return f"{m.group(1)} {m.group(2)} leader"
    return _ROLE.sub(leader, text)
