"""A misspelt word of a place's name, seen before the places are corrected (issue 29).

The slips read back before the parse ("form" for "from") look for a place phrase after the slip; a
sentence with two slips ("heads form her ofice to the boardroom") had none, since "ofice" is no word
the world names places by. A word that is no English word and is one edit from a name word of the
world (four letters or more) counts as that name word here; the places pass corrects it later."""

from __future__ import annotations

from grove_tui.language.parser import known_word
from grove_tui.language.places import PlaceIndex
from grove_tui.language.spelling import one_edit


def misspelt_name_word(low: str, index: PlaceIndex) -> bool:
    """Whether `low` (lowercase) is no English word and one edit from a word of the world's place names."""
    if len(low) < 4 or not low.isalpha() or known_word(low):
        return False
    return any(one_edit(low, name) for name in index.name_words)
