"""A person of a chat list said with what they are doing and no verb (round 69): "teen doing homework in
bedroom 2, gran on the settee, bot drives from the hall to the lounge", "lad reading in the kitchen,
grandad on the balcony". Given its article (chat_articles.py), the first item "a teen doing homework in
bedroom 2" was read as a noun phrase with no clause, and the person lost. In a chat message (typed in
lower case), a first item that opens with a person and an "-ing" word, with no verb of its own before its
comma, is said with "is" (and "a" when typed bare): "a teen is doing homework in bedroom 2". Prose ("A nurse pushing a trolley, a
porter and ...") is left alone."""

from __future__ import annotations

import re

from grove_tui.language import lexicon as lx
from grove_tui.language.tokens import verb_lemma

_ITEM = re.compile(r"(?P<lead>^)(?P<who>(?:(?:an?|the|our|my)\s+)?[a-z'-]+)\s+(?P<ing>[a-z]{2,}ing)\b"
                   r"(?P<rest>[^,;]*)")
_NOT_VERBS = frozenset("building ceiling evening morning wedding clothing thing something nothing anything everything "
                       "king ring spring string sibling darling duckling sing bring swing wing ping".split())


def with_chat_ing_items(text: str) -> str:
    """The text with "is" before the "-ing" word of a verbless chat item of a person (module doc)."""
    if not text or not text[0].islower() or "," not in text:
        return text

    def said(m: re.Match[str]) -> str:
        person = m.group("who").split()[-1]
        if person not in lx.PERSON_NOUNS or m.group("ing") in _NOT_VERBS:
            return m.group(0)
        if any(verb_lemma(w) != w and verb_lemma(w) in lx.INTENT_VERBS and not w.endswith("ing")
               for w in m.group("rest").split()):
            return m.group(0)  # "a lad reading a book walks ...": the item has its verb
        who = m.group("who") if " " in m.group("who") else ("an " if person[0] in "aeiou" else "a ") + person
        return f"{m.group('lead')}{who} is {m.group('ing')}{m.group('rest')}"
    return _ITEM.sub(said, text, count=1)
