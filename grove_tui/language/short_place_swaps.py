"""A three-letter place word with two neighbouring letters swapped ("the rehab gmy": gym).

Misspelt place words are put right against the world's name words of four letters or more, since a
short word one edit from a short name is too often a real word ("left" is not "lift"). A swap of
two neighbouring letters in a three-letter word that is no dictionary word (the tagger's vocabulary holds "gmy"), and that gives a word of a
place's name completing that name with the word next to it ("rehab gmy", "the gmy hall"), is a
typo with only one reading; nothing else about short words changes."""

from __future__ import annotations

from grove_tui.language.parser import dictionary_word
from grove_tui.language.places import PlaceIndex


def swapped_short_word(low: str, before: str, after: str, index: PlaceIndex) -> str | None:
    """The three-letter name word `low` is a swap of neighbouring letters of, when it completes a
    name with the content word before or after it; None otherwise."""
    if len(low) != 3 or not low.isalpha() or dictionary_word(low):
        return None
    swaps = {low[:k] + low[k + 1] + low[k] + low[k + 2:] for k in range(len(low) - 1)} - {low}
    found = sorted(v for v in swaps if (before, v) in index.name_pairs or (v, after) in index.name_pairs)
    return found[0] if len(found) == 1 else None
