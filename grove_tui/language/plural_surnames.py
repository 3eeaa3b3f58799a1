"""A family said by its surname in the plural is one family, as many as "a family" is when nothing
says how many: "The Smiths sit in the living room", "... while the Joneses watch TV in the lounge".
Before, the surname was nobody (no list names it) or a vague crowd, and the sentence's second family
was lost. The word tells itself apart by its capital: after "the", a capital is put there on purpose."""

from __future__ import annotations

from typing import TYPE_CHECKING

from grove_tui.language.parser import dictionary_word, known_word

if TYPE_CHECKING:
    from grove_tui.language.sentence import Sentence


# "the Browns family", "the Smiths' flat"; and a comma: "The Hendersons, a family of five, ...", "the Lees,
# four of them plus a buggy, ...": a count in apposition says who they are (family_surnames.py)
_SAID_AFTER = frozenset({"'", "'s", "family", "household", "clan", "lot", "party", ","})


def plural_surname(s: Sentence, i: int) -> bool:
    """Whether word i is a surname in the plural after "the": capitalised on purpose (never the
    sentence's first word, after "the"; not all capitals), a proper noun or no English word, before a verb or the
    end of its noun phrase ("the Smiths' flat" is owned, "the Browns family" is said with "family"), and no word
    the world calls a place ("the Gardens", "the Cloisters")."""
    w = s.w[i]
    if i < 1 or s.low[i - 1] != "the" or len(w.text) < 4 or not w.text.endswith("s"):
        return False
    if not w.text[0].isupper() or not w.text[1:].islower():
        return False
    if w.pos != "PROPN" and (w.tag != "NNS" or known_word(s.low[i]) or dictionary_word(s.low[i][:-1])):
        return False  # "The Okafors" tagged a common noun: a word no English dictionary holds
    if (i + 1 < s.n and (s.w[i + 1].pos == "PART" or s.low[i + 1] in _SAID_AFTER)):
        return False
    return not s.index.knows(s.low[i]) and not s.index.knows(s.lemma(i)) and not s.index.knows(s.low[i][:-1])
