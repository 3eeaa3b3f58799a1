"""Counted items of a chat list (round 54): "6 ppl in mtg room 1, 2 sales reps @ fridge, 1 sysadmin in
comms room", "approx 150 delegates @ plenary hall, 4 speakers in green rm". A list of "<count> <noun>
<preposition> <place>" items, split by commas, one of which counts a known word for people, is a list
of groups: each other item counted the same way is people too, though its noun is one the reader does
not know ("sysadmin") or takes for a thing by itself ("speakers": loudspeakers). A noun naming the
robot, a thing carried or a building, or a place of the world by itself, is no one."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.sentence import Sentence

# Words of an item's count before its figure: "approx 150 delegates", "about 20 kids".
_ABOUT = frozenset("approx approximately about around roughly circa ~ some like nearly almost over".split())
# Prepositions of an item's place: "in mtg room 1", "@ fridge", "by the bar".
_AT = frozenset("in at by on inside outside near".split())


def chat_list_item(s: Sentence, i: int) -> bool:
    """Whether the noun at i is one counted item of a chat list of counted people (module doc)."""
    lem = s.lemma(i)
    if lem in lx.ROBOT_WORDS or lem in lx.CARRYING_THINGS or lem in lx.BUILDING_WORDS or \
            s.w[i].pos not in ("NOUN", "PROPN", "VERB"):
        return False
    item = _item(s, i)
    if item is None:
        return False
    match = s.index.match((lem,))
    if match is not None and match.exact:
        return False  # "2 fridges": no, a place or thing of the world by itself
    others = [k for k in _heads(s) if k != i]
    return any(s.lemma(k) in lx.PERSON_NOUNS or s.low[k] in lx.PERSON_NOUNS for k in others)


def _item(s: Sentence, i: int) -> int | None:
    """The start of the item whose noun is at i: a count (maybe "approx" before it) at the list's
    start or after a comma, a place preposition after the noun, or None."""
    if i + 2 >= s.n or s.low[i + 1] not in _AT:
        return None
    k = i - 1
    while k >= 0 and s.w[k].pos in ("NOUN", "ADJ") and k >= i - 2 and not s.is_punct(k) and s.w[k].pos != "NUM":
        k -= 1  # "2 sales reps": a word before the head
    if k < 0 or (s.w[k].pos != "NUM" and not s.low[k].isdigit()):
        return None
    start = k - 1 if k > 0 and s.low[k - 1] in _ABOUT else k
    if start > 0 and not (s.is_punct(start - 1) and s.low[start - 1] in (",", ";")):
        return None
    return start


def _heads(s: Sentence) -> list[int]:
    """The nouns of every counted item of the sentence's list."""
    out = []
    for i in range(1, s.n - 2):
        if s.w[i].pos in ("NOUN", "PROPN", "VERB") and _item(s, i) is not None:
            out.append(i)
    return out


# Endings of a word for someone by what they do ("speaker", "operator", "florist", "technician").
_DOER_ENDINGS = ("er", "or", "ist", "ian")


def chat_list_doer(s: Sentence, i: int) -> bool:
    """Whether a word the reader otherwise takes for a thing ("speakers": loudspeakers) is a doer counted
    as one item of a chat list of people: its lemma ends as a word for someone who does something
    ("2 suitcases by the lifts" stays things)."""
    return s.lemma(i).endswith(_DOER_ENDINGS) and chat_list_item(s, i)
