"""People listed one by one as a sentence's subject, roles and relatives among the names (round 72):
"The presenter, her guest and a floor runner walk together ...", "Nadia, her little brother and their
grandpa leave ...", "Sister Quinn, Dr Patel and a registrar hurry ..." are one group of that many who
go together, like a list of names (`named_lists.py`). Kept only for three or more members (a comma in
the list), each one person: a name (titled or not: "Dr Patel") or one person word after "the", "a",
"an" or an owner ("her", "their"), with at most two words before it ("a floor runner", "her little
brother"), one of them at least a name or someone's relative. A list with a count in it ("A doctor, two nurses and a porter") or a pair ("the bride and
her dad", the older sets' two groups) is left alone."""

from __future__ import annotations

import re

from grove_tui.language import lexicon as lx
from grove_tui.language.named_lists import _NOT_NAMES

_NUMBER = {3: "Three", 4: "Four", 5: "Five", 6: "Six"}
_PERSON = lx.PERSON_NOUNS | lx.KIN_NAMES | lx.PERSON_THINGS
_NAME = r"[A-Z][a-z]+(?:-[A-Z][a-z]+)?"
_ROLE = r"(?:[Tt]he|[Aa]n?|[Hh]er|[Hh]is|[Tt]heir|[Oo]ur|[Mm]y)\s+(?:[a-z-]+\s+){0,2}?[a-z]+"
_TITLED = r"[A-Z][a-z]+\.?\s+" + _NAME
_MEMBER = rf"(?:{_ROLE}|{_TITLED}|{_NAME})"
_LIST = re.compile(rf"(^|[.!?;]\s+)({_MEMBER}(?:\s*,\s*{_MEMBER})+\s*,?\s+and\s+{_MEMBER})(?=\s+[a-z])")
_SPLIT = re.compile(r"\s*,\s*(?:and\s+)?|\s+and\s+")
_DETERMINERS = frozenset({"the", "a", "an", "her", "his", "their", "our", "my"})
_NOT_WORDS = frozenset({"and", "or", "with", "of", "to", "from", "at", "in", "on", "by", "is", "are"})


def _one_person(member: str) -> bool:
    words = member.split()
    if words[0].lower() in _DETERMINERS:
        rest = [w.lower() for w in words[1:]]
        return bool(rest) and rest[-1] in _PERSON and not set(rest) & _NOT_WORDS
    if len(words) == 2:  # "Dr Patel", "Sister Quinn"
        return words[0].lower().rstrip(".") in lx.TITLES
    low = words[0].lower()  # a name, not a fronted word ("Plastered, the best man and his brother ...")
    return len(words) == 1 and low not in _NOT_WORDS and low not in _NOT_NAMES and \
        not low.endswith(("ed", "ing", "ly", "ous", "ful", "less", "ish"))


def _listed(m: re.Match[str]) -> tuple[str, int] | None:
    """The list's counted plural and where the list ends, or None when it is no list of people."""
    members = [w for w in _SPLIT.split(m.group(2)) if w]
    end = m.end(2)
    if members and not _one_person(members[-1]):  # "a floor" of "a floor runner walk": a word more
        after = list(re.finditer(r"\S+", m.string[end:]))
        for n in (1, 2):
            words = [a.group(0) for a in after[:n]]
            if len(after) > n and all(re.fullmatch(r"[a-z-]+", w) for w in words) \
                    and _one_person(" ".join([members[-1], *words])):
                members[-1] = " ".join([members[-1], *words])
                end += after[n - 1].end()
                break
    if len(members) not in _NUMBER or len(set(members)) < len(members):
        return None
    if not all(_one_person(w) for w in members):
        return None
    if not any(w.split()[0].lower() in _DETERMINERS or len(w.split()) == 2 for w in members):
        return None  # names only: `named_lists.py`
    if all(w.split()[0].lower() in ("the", "a", "an") for w in members):
        return None  # "A dad, a mum and a kid", "The surgeon, a nurse and a porter": a group each (older sets)
    return f"{m.group(1)}{_NUMBER[len(members)]} people", end


def with_role_lists(text: str) -> str:
    """The text with a subject list of three or more single people written as one counted plural."""
    out, at = [], 0
    for m in _LIST.finditer(text):
        if m.start() < at:
            continue
        said = _listed(m)
        if said is None:
            continue
        out.append(text[at:m.start()] + said[0])
        at = said[1]
    return "".join(out) + text[at:]
