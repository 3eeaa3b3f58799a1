"""An order to have someone go somewhere or do something there (round 44): "..., and have a nursing
auxiliary wheel linen out of the stores up to ward 3", "Have a porter take the bloods to the lab", "let
the kids play in the soft play". The parser takes the person for the object of "have" and the verb
for a noun, so the person was lost, or read as a vague crowd. Said as the person's own clause ("a
nursing auxiliary wheels linen ..."), set off from what comes before it by a semicolon so that no
one before shares its verb, they are one group like any other. Only a verb the lexicon
knows for people going, staying or taking something along follows the person, so "have a look" or
"get everyone out" are left alone; orders to work a post are language/work_imperatives.py's."""

from __future__ import annotations

import re

from grove_tui.language import lexicon as lx
from grove_tui.language.work_imperatives import _PERSON, _ROBOT, _singular
from grove_tui.language.tokens import third_person

# Verbs an order can set someone to: going, staying, leading and carrying ("wheel", "take", "bring").
_ORDERED = frozenset(lx.INTENT_VERBS) | lx.LEADING_VERBS | frozenset(
    "wheel push pull carry take bring fetch drag haul lug ferry deliver collect escort".split())
_NOT_ORDERED = frozenset({"look", "go", "get", "make", "have", "be", "do", "let", "run", "move"})
_VERBS = "|".join(sorted((v for v in _ORDERED - _NOT_ORDERED if v.isalpha()), key=len, reverse=True))
_ORDER = re.compile(r"(^|[.!?;:]\s+|\s*,?\s*\b(?:and|then|so|please)\s+|,\s+)(?:please\s+)?(?:[Hh]ave|[Gg]et|[Ll]et|[Mm]ake)\s+"
                    rf"({_PERSON})\s+({_VERBS})\b(?!-)")
# People with any number said in words ("twelve pupils", "a few porters").
_NUMBERS = "|".join(sorted(set(lx.UNITS) | set(lx.TENS) | {"a few", "several", "a dozen", "a handful of"}, key=len, reverse=True))
_COUNTED = rf"(?:(?:{_NUMBERS})(?:\s+(?!to\b)[a-z][\w'-]*){{1,3}}?)"
# Asked, told or wanted to ("Get a porter to take ...", "Tell three guards to wait ...", "I'd like five shoppers
# to queue ...", "we need a cleaner to walk ..."): the same order, said with "to".
_ASKED = re.compile(r"(^|[.!?;:]\s+|\s*,?\s*\b(?:and|then|so|please)\s+|,\s+)(?:please\s+)?"
                    r"(?:(?:[Ii]|[Ww]e)(?:'d|’d|\s+would|\s+also|\s+really)?\s+(?:like|need|want|love)|[Gg]et|[Tt]ell|"
                    r"[Aa]sk|[Ii]nstruct|[Oo]rder|[Nn]eed|[Ww]ant|[Aa]llow)\s+"
                    rf"({_PERSON}|{_COUNTED})\s+to\s+({_VERBS})\b(?!-)")


def as_ordered_clauses(text: str) -> str:
    """The text with an order to go or do something said as the person's own clause (module doc)."""
    def said(m: re.Match[str]) -> str:
        person, verb = m.group(2), m.group(3)
        if any(w.lower() in _ROBOT for w in person.split()) or person.split()[-1].lower() in _ORDERED:
            return m.group(0)
        lead = m.group(1)
        said = " ".join(lead.replace(",", " ").split()).lower()
        if said in ("", "and", "so") and lead.strip():
            lead = "; "  # "Station a guard at X and have two volunteers carry ...": their own clause, no shared verb
        elif said == "then":
            lead = "; then "
        if not lead.strip() or lead.strip()[-1] in ".!?:":
            person = person[:1].upper() + person[1:]  # a sentence's first word, as written
        return f"{lead}{person} {third_person(verb) if _singular(person) else verb}"
    return _ASKED.sub(said, _ORDER.sub(said, text))
