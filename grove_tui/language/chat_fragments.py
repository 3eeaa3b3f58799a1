"""Chat items with no verb but an "-ing" word (round 43): "3 from sales gossiping @ copier, 1 making toast
in kitchen", "3 engineers + the intern arguing in mtg rm 2"; and a count with an article before "from"
("the two from the chess club", round 58).

- A count alone at the start of an item, before "from" or an "-ing" word, counts people: "3 from sales"
  is "3 people from sales", "1 making toast" is "1 person making toast" (the parser read the bare figures
  as one vague group of the whole sentence).
- A counted plural joined to one person said with a determiner ("3 engineers and the intern",
  "2 nurses and a porter") before an "-ing" word takes "are": without a verb the parser may read the
  "-ing" word as a noun and drop the second person.
An "-ing" word naming a room ("2 meeting rooms", "the waiting area") is no verb and is left alone.
"""

from __future__ import annotations

import re

from grove_tui.language import lexicon as lx
from grove_tui.language.tokens import lemma

_NUMBER = r"(?:\d+|one|two|three|four|five|six|seven|eight|nine|ten|eleven|twelve|fifteen|twenty)"
_ITEM_START = r"(^|[,;:]\s*)"
# "3 from sales", "1 making toast": the count alone, then "from" or an "-ing" word.
_BARE_COUNT = re.compile(_ITEM_START + r"(" + _NUMBER + r")\s+(?=(from\s+[a-z]|[a-z]{3,}ing\b))", re.IGNORECASE)
# "the two from the chess club", "those three from accounts" (round 58): with an article before the count
# the parser read "the two" as nobody. Words only: "the 10 from Leeds" is a train.
_WORD_NUMBER = (r"(?:two|three|four|five|six|seven|eight|nine|ten|eleven|twelve|thirteen|fourteen|fifteen|sixteen|"
                r"seventeen|eighteen|nineteen|twenty|thirty|forty|fifty)")
_COUNTED_FROM = re.compile(r"\b((?:the|those|these|all(?:\s+the)?)\s+" + _WORD_NUMBER + r")\s+(?=from\s+[A-Za-z])",
                           re.IGNORECASE)
# "3 engineers and the intern arguing": a counted plural and one person, then an "-ing" word.
_LISTED = re.compile(_ITEM_START + r"(" + _NUMBER + r"\s+([a-z]+)\s+and\s+(?:the|a|an|his|her|their|our|1|one)\s+"
                     r"([a-z]+))\s+(?=([a-z]{3,}ing)\b)", re.IGNORECASE)
# "-ing" words of places and things, not of what people do ("the waiting room", "meeting room 2").
_ROOM_AFTER = re.compile(r"[a-z]+ing\s+(?:rooms?|areas?|halls?|lots?|bays?|spaces?|lounges?|spots?|zones?|"
                         r"tables?|stations?|machines?|desks?|counters?|queues?|lines?)\b", re.IGNORECASE)
# Words in "-ing" that are no verb ("building", "evening"), for every chat pass that looks for one.
ING_NOUNS = frozenset("building buildings ceiling evening morning something nothing anything everything during "
                       "thing king ring sing spring string wing bring".split())


def person_word(word: str) -> bool:
    """Whether a chat word names a person ("porter", "porters")."""
    word = word.lower()
    return word in lx.PERSON_NOUNS or lemma(word) in lx.PERSON_NOUNS


def chat_fragments(text: str) -> str:
    """The text with verbless chat items written with their people and verb (see the module doc)."""
    def bare(m: re.Match[str]) -> str:
        rest = text[m.end():]
        words = rest.split()
        word = words[0].lower() if words else ""
        if word in ING_NOUNS or _ROOM_AFTER.match(rest) or len(words) > 1 and person_word(words[1].strip(",.;:")):
            return m.group(0)  # "three giggling teenagers run": the "-ing" word describes the people said after it
        one = m.group(2).lower() in ("1", "one")
        return f"{m.group(1)}{m.group(2)} {'person' if one else 'people'} "

    def listed(m: re.Match[str]) -> str:
        rest = text[m.end():]
        if m.group(5).lower() in ING_NOUNS or _ROOM_AFTER.match(rest) or not person_word(m.group(3)) \
                or not person_word(m.group(4)) or m.group(3).lower() == lemma(m.group(3).lower()):
            return m.group(0)
        return f"{m.group(1)}{m.group(2)} are "

    text = _LISTED.sub(listed, text)
    return _BARE_COUNT.sub(bare, text)


def with_counted_from(text: str) -> str:
    """The text with "the two from X" written "the two people from X", as "3 from sales" is."""
    return _COUNTED_FROM.sub(lambda m: f"{m.group(1)} people ", text)
