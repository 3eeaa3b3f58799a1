"""Compound place nouns the words alone would misread, for the place index (language/places.py):

- a word for a whole building with a noun before it that says what kind ("the garden centre", "the
  boat house", "the sports complex") names a kind of place, not the building the scene is in, unless the
  phrase is near in meaning to what this world is ("the shopping centre" of a mall, "the medical centre"
  of a hospital); a world that has no place of that kind refuses it rather than read it as nowhere;
- a phrase whose head is only the first word of a two-word name ("the garden centre" against "centre
  court", "the ticket box" against "box office") shares a modifier with that place, not what it is.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

from grove_tui.language.lexicon import PLACE_MODIFIERS
from grove_tui.language.parser import known_word
from grove_tui.language.place_other_kinds import names_a_kind
from grove_tui.language.place_modifiers import PERSON_ADJECTIVES

if TYPE_CHECKING:
    from grove_tui.language.places import PlaceEntry, PlaceIndex
    from grove_tui.language.sentence import Sentence

# Building words that take a noun before them to name a kind of place ("garden centre", "guest house",
# "leisure complex"); "building", "site" and "premises" with a noun are the scene's own ("the office
# building"), so they stay words for the whole building.
KIND_HEADS = frozenset("centre center complex facility house".split())
# Nouns before "centre" that put the place outside any building ("the town centre"): no kind of room.
SURROUNDINGS = frozenset("town city village".split())
# A compound this near in meaning to the world's own name is that building ("shopping centre" is 0.63
# from "supermarket" and 0.67 from "mall", "medical centre" 0.73 from "hospital", "leisure centre" 0.77
# from "sports centre"); kinds no such world is come no nearer than 0.44 ("garden centre" to a mall,
# "data centre" 0.29 to a supermarket, "day centre" 0.38 to a hospital, "shopping centre" 0.47 to a
# town square: the gap between 0.47 and 0.63 is where the line goes).
OF_THIS_BUILDING = 0.52
# A head that is a word of the world's own name ("bank" of a food bank, "unit" of a dialysis unit) with
# another noun before it names the building only when nearer still: "renal unit" is 0.79 from "dialysis
# unit", while "clothes bank" (0.58) and "baby bank" (0.62) are other kinds of bank than a food bank.
OF_THIS_NAME = 0.65


def names_another_kind(index: PlaceIndex, content: Sequence[str]) -> bool:
    """Whether a phrase headed by a building word names a kind of place rather than the building: a
    noun before the head that is no word of the building, and the whole not near what this world is."""
    own_name = len(content) >= 2 and content[-1] in world_name_words(index)
    if len(content) < 2 or content[-1] not in KIND_HEADS and not own_name:
        return False
    kinds = [t for t in content[:-1] if t not in index.building_words and t.isalpha() and known_word(t)]
    if not kinds or any(t in SURROUNDINGS for t in kinds):
        return False
    near = index.near_building(" ".join(content))
    return near < OF_THIS_BUILDING or own_name and content[-1] not in KIND_HEADS and 0.0 < near < OF_THIS_NAME


def world_name_words(index: PlaceIndex) -> frozenset[str]:
    """The words of the world's own name ("food", "bank" of a food bank)."""
    return frozenset(str(getattr(index.world, "name", "") or "").lower().replace("_", " ").split())


def head_only_modifies(entry: PlaceEntry, content: Sequence[str]) -> bool:
    """Whether the phrase's head names this place only as the first word of a longer name ("centre" of
    "centre court" for "the garden centre"), and no other word of the phrase is one of its words: the
    place is another kind of thing. A name whose next word is a number or letter ("ward c", "gate 2")
    keeps its kind first, so it still counts."""
    if len(content) < 2:
        return False
    head = content[-1]
    if any(head in kind.split() for kind in entry.types) or any(t in entry.tokens for t in content[:-1]):
        return False
    holding = [p for p in entry.phrases if head in p]
    return bool(holding) and all(
        p.index(head) < len(p) - 1 and p[p.index(head) + 1].isalpha() and len(p[p.index(head) + 1]) > 1
        for p in holding)


def modified_otherwise(entry: PlaceEntry, modifiers: Sequence[str], head: str) -> bool:
    """Whether every name of the place holding the phrase's head has another word right before it than
    the phrase's modifiers: "the travel centre" against "the garden centre", "coffee shop" against "pet
    shop". Such a name is a kind of that head, and the phrase names another kind; a name that is the
    head alone ("shop") or a head the world does not qualify is no evidence either way."""
    holding = [p for p in entry.phrases if head in p]
    # a misspelt modifier ("the chek-in hall") says no kind: the phrase as a whole decides, as before
    return bool(holding) and all(p.index(head) > 0 and p[p.index(head) - 1] not in modifiers for p in holding) \
        and all(names_a_kind(t, entry) for t in modifiers)


def noun_like_adjective(s: Sentence, x: int) -> bool:
    """Whether a word the parser tags an adjective before a place's head may be the noun of a compound
    ("pet" of "the pet shop", "sweet" of "the sweet shop": the small model tags both JJ), so that it is
    checked against the place like any kind before the head. Not a word that says how a place looks or
    lies ("the quiet lounge", "the back office"), nor one only people take ("the nervous ..."), nor an
    adjective by its ending ("the medical ...", "the electronic ...") or a comparison ("the busiest")."""
    low = s.low[x]
    return s.w[x].pos == "ADJ" and s.w[x].tag == "JJ" and s.w[x].dep in ("amod", "compound") and low.isalpha() \
        and low not in PLACE_MODIFIERS | PERSON_ADJECTIVES | _DESCRIBING and not low.endswith(_ADJECTIVE_ENDINGS) \
        and known_word(low + "s")  # a noun has a plural English uses ("pets", "sweets"; no "vasts", "nices")


# Adjectives with a plural as nouns that still describe a place when before its head ("the cold store" is
# a name, but "the cold lounge" a lounge): colours and the commonest looks.
_DESCRIBING = frozenset("""cold cool clean narrow short high long great regular local special ancient bright
secure green blue red white black yellow silver""".split())
# Endings English adjectives are made with: a word that has one is no noun of a compound.
_ADJECTIVE_ENDINGS = ("al", "ic", "ous", "ful", "ive", "able", "ible", "less", "ish", "ary", "ern", "est", "ian",
                      "ese", "ent", "ant", "y")
