"""An order to set someone to work at a post (round 31): "Have Janet man the front desk while two
contractors perch on the waiting sofa", "Get Sam to staff the till", "Have the porter mind the door".
The small parser reads "Janet man" as one noun and the order's verb as the sentence's, so the person
at the post is lost. Said as the person's own clause ("Janet mans the front desk"), they are one group
at the post like any other. Only a verb of working a post follows the person, so "have a look" or
"get everyone out" are left alone."""

from __future__ import annotations

import re

from grove_tui.language.tokens import third_person

_WORK = ("man", "staff", "mind", "run", "cover", "watch", "work", "guard", "tend", "attend", "supervise",
         "manage", "oversee", "look after", "keep an eye on", "keep watch at", "keep watch over", "hold")
_PERSON = (r"(?:[A-Z][\w'-]*(?:\s+[A-Z][\w'-]*){0,2}"  # "Janet", "Janet Okoye"
           r"|(?:the|a|an|our|their|his|her|one|two|three|four|five|six|some|a\s+couple\s+of|\d+)"
           r"(?:\s+(?!to\b)[a-z][\w'-]*){1,3}?)")
_WORK_RE = "|".join(w.replace(" ", r"\s+") for w in _WORK)
_ORDER = re.compile(r"(^|[.!?;:,]\s+|\b(?:and|then|so|please)\s+)(?:please\s+)?(?:[Hh]ave|[Gg]et|[Ll]et|[Mm]ake)\s+"
                    rf"({_PERSON})\s+(?:to\s+)?({_WORK_RE})\b")
_ROBOT = frozenset({"robot", "robots", "bot", "droid", "it"})
_PLURAL_HEADS = frozenset({"people", "staff", "men", "women", "children", "police", "folk", "crew"})


def _singular(person: str) -> bool:
    words = person.split()
    if words[0][:1].isupper() and words[0].lower() not in ("the", "a", "an", "our", "their", "his", "her", "one",
                                                            "two", "three", "four", "five", "six", "some"):
        return True  # a name
    if words[0].lower() in ("a", "an", "one"):
        return True
    if words[0].lower() in ("the", "our", "their", "his", "her"):
        last = words[-1].lower()
        return not (last.endswith("s") and not last.endswith("ss")) and last not in _PLURAL_HEADS
    return False


def as_workers(text: str) -> str:
    """The text with an order to work a post said as the worker's own clause (module doc)."""
    def said(m: re.Match[str]) -> str:
        person, verb = m.group(2), " ".join(m.group(3).split())
        if any(w.lower() in _ROBOT for w in person.split()):
            return m.group(0)  # "have the robot watch the door": the robot's own task
        return f"{m.group(1)}{person} {third_person(verb) if _singular(person) else verb}"
    return _ORDER.sub(said, text)
