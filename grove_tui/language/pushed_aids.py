"""An aid pushed in a fronted clause before one who takes someone somewhere (round 46): "Pushing a
wheelchair, a porter takes a patient from the pharmacy to the exit", "Pushing one of the store's
wheelchairs, an assistant brings a shopper to the café". The aid is how the one taken goes; said as the
mover's own verb ("a porter pushes a wheelchair and takes ..."), the leading verb became a second verb
and the mover lost the way. fronted_movers.py leaves the fronted clause out when the leading verb has a
person after it: this module says whether it has."""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language import lexicon as lx
from grove_tui.language.parser import Word
from grove_tui.language.tokens import lemma



def after_is_someone(words: Sequence[Word], verb: int) -> bool:
    """Whether the words after the verb at `verb` name a person (within four words: "a pensioner", "the
    frail old man", "her dad"), before any preposition."""
    for w in words[verb + 1:verb + 6]:
        if w.pos == "ADP" or w.text in (",", ";", ":", "."):
            return False
        if lemma(w.lower) in lx.PERSON_NOUNS and lemma(w.lower) not in lx.NON_PEOPLE:
            return True
    return False
