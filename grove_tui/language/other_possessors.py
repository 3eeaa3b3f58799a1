"""A place named by a word that sets it apart which the world's place of that kind lacks: "the members'
enclosure" of a racecourse whose only enclosure is the winners', "the VIP lounge" where the one lounge
is the owners' and trainers'. The head ("enclosure") matches, often by a bare alias, but the word
before it names another place of that kind, so the phrase is refused, not read as the one the world
has, and not matched by meaning either (round 47). A word the place has ("the winners' enclosure"),
a synonym of one, a place owned by a kind of person ("the kids' bedroom") or a word of the building
("the racecourse bar") is no other place. The owner may be written without an apostrophe, as a noun
before the head ("the VIP lounge", "the members bar"): a kind of person all the same (round 48)."""

from __future__ import annotations

from collections.abc import Callable, Sequence

from grove_tui.language import lexicon as lx
from grove_tui.language.places import PlaceIndex, PlaceMatch
from grove_tui.language.sentence import IDENTIFIER, Sentence

_POSSESSIVE = ("'s", "'", "’s", "’")


def setting_words(s: Sentence, first: int, end: int, is_person_noun: Callable[[int], bool]) -> tuple[str, ...]:
    """The words before a place phrase's head that set one place of its kind apart: a person said as
    its owner ("members'", "VIP"), or a noun no place of the world is called by ("VIP")."""
    index = s.index
    words: list[str] = []
    for x in range(first, end - 1):
        low = s.low[x]
        if s.is_punct(x) or low in lx.DETERMINERS or low in _POSSESSIVE or IDENTIFIER.fullmatch(low):
            continue
        word = s.lemma(x)
        if word in lx.PLACE_MODIFIERS or word in index.building_words:
            continue
        # "the VIP lounge": an owner without the apostrophe, unless a room of the world is theirs under
        # another head ("the staff lounge" with a staff room), left to the other matchers
        owner = x + 1 < end and is_person_noun(x) and (s.low[x + 1] in _POSSESSIVE or s.w[x].pos in ("NOUN", "PROPN")
                                                       and not any(e.kind == "zone" and word in e.tokens for e in index.entries))
        if owner or (s.w[x].pos in ("NOUN", "PROPN") and not index.knows(word) and not is_person_noun(x)):
            words.append(word)
    return tuple(words)


def other_of_kind(index: PlaceIndex, match: PlaceMatch | None, lemmas: Sequence[str], words: Sequence[str]) -> bool:
    """Whether the matched place is another of the phrase's kind: the phrase's head is one of its
    words, a word setting the phrase apart is none of its words, and the place is itself set apart by
    a word of its own the phrase does not say ("winners'" of "the winners' enclosure")."""
    if match is None or not words or not lemmas:
        return False
    entry = index.entry(match.name)
    if entry is None:
        return False
    head = lemmas[-1]
    if head in lx.GENERIC_PLACE_HEADS or head not in entry.tokens or any(index.names_word(entry, w) for w in words):
        return False
    owners = [w for w in words if w in lx.PERSON_NOUNS]
    said = set(lemmas)
    own = [p for p in entry.phrases if len(p) > 1 and p[-1] == head]
    if _whose(entry.said, head):
        return bool(own) and not any(set(p) <= said for p in own)
    # "the VIP lounge" matched by its head to a "champagne lounge" where the world's lounge for people is
    # the owners' and trainers': a lounge of another kind of person, which the world does not have
    kin = [e for e in index.entries if e.kind == "zone" and head in e.tokens]
    return bool(owners) and any(_whose(e.said, head) for e in kin)


def _whose(said: Sequence[str], head: str) -> bool:
    """Whether a place is set apart by whose it is, as the world writes it ("winners' enclosure"), not
    by a kind ("lobby bar")."""
    return any(("' " in n or "’ " in n or "'s " in n or "’s " in n) and n.split()[-1].startswith(head) for n in said)
