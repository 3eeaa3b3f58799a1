"""People named in a list as a sentence's subject ("Jo, Sam and Priya walk ...", "Ama, Kofi and their
gran stroll ...") are one group of that many, walking together, not a group per name (the sets'
convention: a list of names states only its size). Written before parsing as one counted plural
("Three people walk ..."), kept only for three or more members (a comma in the list) whose every
member is one capitalised name, or a kin word after "their"/"his"/"her"/"our"/"my" as the last."""

from __future__ import annotations

import re

_NUMBER = {3: "Three", 4: "Four", 5: "Five", 6: "Six", 7: "Seven", 8: "Eight"}
_NAME = r"[A-Z][a-z]+(?:-[A-Z][a-z]+)?"
_KIN = r"(?:their|his|her|our|my)\s+[a-z]+"
_LIST = re.compile(r"(^|[.!?;]\s+)(" + _NAME + r"(?:\s*,\s*" + _NAME + r")+\s*,?\s+and\s+(?:" + _NAME + "|" + _KIN
                   + r"))(?=\s+[a-z])")
_SPLIT = re.compile(r"\s*,\s*(?:and\s+)?|\s+and\s+")
# Capitalised words that open a sentence but are no one's name.
_NOT_NAMES = {"the", "a", "an", "at", "in", "on", "by", "while", "when", "after", "before", "then", "now", "today",
              "tonight", "meanwhile", "later", "first", "next", "finally", "also", "and", "but", "so", "have", "get",
              "let", "make", "send", "put", "place", "set", "add", "please", "this", "that", "these", "those", "some",
              "all", "both", "every", "each", "here", "there", "from", "to", "into", "with", "during", "once", "as",
              "if", "mum", "dad", "mom", "gran", "grandad", "grandma", "grandpa", "nan", "ward", "gate", "bay",
              "room", "platform", "level", "floor", "block", "reception", "monday", "tuesday", "wednesday",
              "thursday", "friday", "saturday", "sunday", "robot"}


def _named(m: re.Match[str]) -> str:
    members = [w for w in _SPLIT.split(m.group(2)) if w]
    names = [w for w in members if not re.fullmatch(_KIN, w)]
    if len(members) not in _NUMBER or any(w.lower() in _NOT_NAMES for w in names):
        return m.group(0)
    if len(set(members)) < len(members):
        return m.group(0)
    return f"{m.group(1)}{_NUMBER[len(members)]} people"


def with_named_lists(text: str) -> str:
    """The text with a subject list of three or more names written as one counted plural (module doc)."""
    return _LIST.sub(_named, text)
