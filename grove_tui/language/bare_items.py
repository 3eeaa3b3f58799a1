"""Items of a chat list said with no determiner ("8 people in queue at till 2, staff member restocking
aisle 3", "ceo and 2 VPs in boardroom, intern at printer", "8 undergrads in chem lab and technician
at fume cupboards"): a bare singular word for a person opening an item, after an item that said its
place, is one person, written with "a" (so is a word no list knows in "his" or "her" own place: "gaffer in
his office", language/own_place_items.py) so the parser reads a group of its own. A word for people in
the plural, a word the lexicon keeps for many ("staff", "security"), or an item with no place before
it ("a mother and child at the desk") or after a place said as an item of its own ("marketing lot, 5
people, in huddle room 2, boss in her office": whose place it is the places decide) is left as it is."""

from __future__ import annotations

import re

from grove_tui.language import lexicon as lx
from grove_tui.language.item_doings import doing_word
from grove_tui.language.own_place_words import own_place
from grove_tui.language.tokens import lemma

_PLACED = frozenset("in at on by near inside outside behind beside".split())
_AFTER = _PLACED | frozenset("restocking waiting queuing queueing sitting standing working cleaning mopping "
                             "serving chatting reading sleeping".split())
# An item's start: a comma or "and" after the text of an item before it.
_ITEM = re.compile(r"(?P<sep>,\s+|\s+and\s+)(?P<first>[a-z]+)(?:\s+(?P<second>[a-z]+))?\s+(?P<after>[a-z]+)\b")
_MANY = frozenset("security management admin personnel crew team family couple group class staff police "
                  "everyone everybody people crowd".split())
_TWO_WORD = frozenset({("staff", "member"), ("team", "member"), ("crew", "member"), ("shop", "assistant"),
                       ("security", "guard"), ("sales", "assistant"), ("care", "worker"), ("lab", "tech")})


def bare_items(text: str) -> str:
    """The text with "a"/"an" before each bare singular person opening a placed item (module doc)."""
    out: list[str] = []
    last = 0
    start = 0  # where the item before the match begins
    for m in _ITEM.finditer(text):
        if m.start() < last:
            continue
        before = text[start:m.start()].lower().split()
        first, second, after = m.group("first"), m.group("second"), m.group("after")
        if second is not None and (first, second) in _TWO_WORD:
            noun, follows = second, after
        elif second is not None and (second in _AFTER or doing_word(second, after)):
            noun, follows = first, second
        elif second is None:
            noun, follows = first, after
        else:
            start = m.start() + len(m.group("sep"))
            continue
        said = bool(before) and before[0] not in _PLACED  # not ", in huddle room 2, boss ...": a place of its own
        if (_bare_person(noun) or own_place(noun, follows, after)) and (follows in _AFTER or doing_word(follows, after if follows != after else None)) and said and _PLACED & set(before):
            article = "an" if first[0] in "aeiou" else "a"
            out.append(text[last:m.start()] + m.group("sep") + article + " ")
            last = m.start() + len(m.group("sep"))
        start = m.start() + len(m.group("sep"))
    out.append(text[last:])
    return "".join(out)


def _bare_person(word: str) -> bool:
    """A singular word for one person (not "nurses", "staff", "security")."""
    listed = word in lx.PERSON_NOUNS or (word.endswith(lx.STRONG_AGENT_SUFFIXES) and len(word) >= 6)  # "keeper"
    return (listed and lemma(word) == word and word not in _MANY
            and word not in lx.IMPLIED_RANGES and word not in lx.DETERMINERS and word not in lx.ROBOT_WORDS)
