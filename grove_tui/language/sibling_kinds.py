"""A kind of place named beside the world's own kind on the same head (issue 29): "the diving pool" of a
water park whose pools are the wave pool and the splash pool, "the beer tent" of a show whose tents are the
food tent and the craft tent. The head matches a place, but that place is called by the head with another
word of kind before it ("wave pool", "food tent"), and the word said is a noun (or "-ing" word) the world
never uses and is not clearly near the place: the phrase names a sibling kind, not that place. The match
is dropped; a place the whole phrase clearly means is still read by meaning ("the eating area" is the
cafeteria, not the waiting area), else the phrase is refused as a place the world lacks.
Adjectives ("the huge pool"), whose it is ("the kids' pool") and words the world uses are left alone, as
is a word clearly near the place ("the swimming pool" is the main pool)."""

from __future__ import annotations

from grove_tui.language import lexicon as lx
from grove_tui.language.place_compounds import noun_like_adjective
from grove_tui.language.places import PlaceMatch
from grove_tui.language.sentence import Sentence

# "-ing" words that say how a place looks or feels, not what kind it is.
_LOOKS = frozenset("amazing boring relaxing inviting sparkling shining heaving steaming freezing thriving "
                   "bustling crowded teeming echoing adjoining neighbouring neighboring existing outgoing".split())
# How near the word of kind must come to the place for a sibling kind to be that place ("swimming" 0.56
# from a wave pool, "diving" 0.49, "beer" 0.35 from a food tent).
SIBLING_NEAR = 0.55


def sibling_kind(s: Sentence, start: int, end: int, match: PlaceMatch | None) -> bool:
    """Whether the phrase from start to end names another kind of the matched place's head (module doc)."""
    if match is None or end - start < 2:
        return False
    index = s.index
    entry = index.entry(match.name)
    head = s.lemma(end - 1)
    words = [x for x in range(start, end - 1) if not s.is_punct(x) and s.low[x] not in lx.DETERMINERS
             and s.lemma(x) not in lx.PLACE_MODIFIERS]
    if entry is None or len(words) != 1 or words[0] != end - 2:
        return False
    x = words[0]
    word = s.lemma(x)
    kind_word = s.w[x].pos in ("NOUN", "PROPN") or s.w[x].tag == "VBG" or noun_like_adjective(s, x) or \
        s.low[x].endswith("ing") and len(s.low[x]) > 5 and s.low[x] not in _LOOKS  # "diving": tagged an adjective
    if not kind_word or word in lx.PERSON_NOUNS or \
            word in index.vocabulary or index.names_word(entry, word) or word in index.building_words:
        return False
    if not any(len(p) == 2 and p[1] == head and p[0] != word for p in entry.phrases):
        return False  # the place is not called by this head with a word of kind
    near = index.by_meaning(word, among={entry.name})
    return not near or near[0].similarity < SIBLING_NEAR
