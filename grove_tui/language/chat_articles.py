"""A person typed bare as an item of a chat list (round 31): "couple checking out the suv, sales guy
hovering nr brochure stand", "nurse at pharmacy, two visitors sitting in the cafeteria". With no
article the small parser makes the first item the list's head noun and the next its apposition, and
one of them is lost. An item that opens with one word of a person (or a modifier and one), followed by
a place word or what they are doing, is said with "a": "a couple checking out ..., and a sales guy
hovering ...", as the reader reads it written out."""

from __future__ import annotations

import re

from grove_tui.language import lexicon as lx

_MASS = frozenset({"staff", "people", "folk", "police", "personnel", "security", "crew", "everyone", "everybody",
                   "someone", "somebody", "anyone", "nobody", "person", "individual", "pedestrian", "one"}) | \
    lx.MEMBERS_NAME_COLLECTIVES | lx.QUANTIFYING_COLLECTIVES | lx.QUEUE_COLLECTIVES | \
    frozenset("troop file group team gang party class tour band squad".split())  # "pupils, troop from ...": a verb
_PREPOSITIONS = ("at", "by", "in", "near", "nr", "on", "@", "beside", "outside", "inside", "next", "w/", "with",
                 "behind", "opposite", "hovering", "outside", "round", "around", "from", "to", "into", "heading")
_ITEM = re.compile(r"(^|[,;]\s*|\bwhile\s+)([A-Za-z][a-z'-]*)(?:\s+([a-z][a-z'-]*))?"
                   r"(?=\s+(\S+))")
# Words in "-ed" that describe a person before their noun, besides the lexicon's (round 46: "tired manager @ X").
_DESCRIBING = frozenset("bored stressed confused lost retired harassed frazzled dazed exhausted flustered annoyed "
                        "frustrated puzzled bewildered disorientated disoriented distracted relaxed delighted "
                        "interested unimpressed red-faced bearded masked hooded uniformed suited armed "
                        "qualified unqualified trained experienced talented dedicated".split())
_NOT_MODIFIERS = frozenset("a an the this that these those my our your his her their its some any no every each "
                           "and or but then at by in on to of with one few several many most all both another other "
                           "more half".split())


def _person(word: str) -> bool:
    low = word.lower()
    return low in lx.PERSON_NOUNS and low not in _MASS


def _describes(word: str) -> bool:
    """An "-ed" or "-ing" word that describes the person after it ("tired", "worried", "waiting"), not a
    verb of the item before it."""
    low = word.lower()
    return low in lx.NP_MODIFIERS or low in _DESCRIBING


def _doing(word: str) -> bool:
    low = word.lower()
    return low in _PREPOSITIONS or (low.endswith("ing") and len(low) > 5)


def with_chat_articles(text: str) -> str:
    """The text with "a" before a person typed bare as a chat item (module doc)."""
    def said(m: re.Match[str]) -> str:
        lead, first, second, nxt = m.group(1), m.group(2), m.group(3), m.group(4)
        if first.lower() in _NOT_MODIFIERS or (first.lower() in lx.NUMBER_WORDS and first.lower() not in ("couple", "pair")) or \
                (first[:1].isupper() and m.start(2) > 0):
            return m.group(0)
        if second is None:
            if not (_person(first) and _doing(nxt)):
                return m.group(0)
        elif _person(first) and _doing(second):
            nxt = second  # "nurse at pharmacy"
        elif (first.lower(), second.lower()) in lx.MULTIWORD_PEOPLE and _doing(nxt):
            pass  # "new starter @ photocopier": a person of two words
        elif not (_person(second) and not _person(first) and _doing(nxt) and first.isalpha() and
                  (not first.endswith(("ing", "ed")) or _describes(first))):
            return m.group(0)  # "sales guy hovering": a modifier and a person; "tired manager @ X" too
        article = "an" if first[:1].lower() in "aeiou" else "a"
        if m.start(2) == 0 and first[:1].isupper():
            article = article.capitalize()
            first = first[:1].lower() + first[1:] if first.lower() in lx.PERSON_NOUNS else first
        rest = f" {second}" if second is not None else ""
        if lead.strip() in (",", ";"):
            lead = f"{lead.rstrip()} and "  # a later item: "..., and a boss in her office", the list's own
        return f"{lead}{article} {first}{rest}"
    return _ITEM.sub(said, text)
