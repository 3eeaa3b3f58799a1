"""A place the world lacks is not rescued by meaning through a shared modifier alone (round 56): "the
beer tent" of a ground whose only beer place is "the beer counter", "the pottery hut" where there is a
"pottery studio". The words already met that place and let it go (its head names another thing); the
looser reading by meaning (place_meaning.rescued), which only spares a refusal, then comes near it for
the modifier's sake. When the phrase's head is none of the place's words (nor a synonym) while one of
its modifiers is (not a word of whose it is), the phrase (one modifier and its head: "silent study full" says more than a name) names another thing of that kind: refused, not read as the place.
"""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language import lexicon as lx
from grove_tui.language.places import PlaceIndex, owner_kinds
from grove_tui.language.user_kinds import USER_KINDS


def only_modifier_shared(index: PlaceIndex, lemmas: Sequence[str], name: str) -> bool:
    """Whether the phrase (lemmas) shares only a modifier with the place `name`, not its head (module doc)."""
    content = [t for t in lemmas if t not in lx.PLACE_MODIFIERS and t not in lx.DETERMINERS and t.isalpha()]
    entry = index.entry(name)
    if entry is None or len(content) != 2 or content[-1] in lx.GENERIC_PLACE_HEADS | lx.BUILDING_WORDS:
        return False
    # an owner shared ("the nurses' post" of the nurses' station) says whose, not what kind: the head may differ
    return not index.names_word(entry, content[-1]) and any(
        index.names_word(entry, t) and not owner_kinds(t) & entry.owners and t not in USER_KINDS for t in content[:-1])
