"""Holding on to a place (round 47): "three beginners cling to the barrier", "a toddler hangs on to the
rail", "two skaters hold on to the boards", "the nervous ones stick close to the wall". "To" after a
verb of holding on says what they hold, where they stay, not where they go: the phrase is read as
"at" it.
"""

from __future__ import annotations

from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import verb_lemma

# Verbs that hold on to a thing with "to" ("cling to"), and those that need "on" first ("hang on to").
_CLINGING = frozenset({"cling", "clings", "clung", "clinging", "cleave", "cleaves", "cleaving"})
_HOLDING_ON = frozenset({"hold", "holds", "held", "holding", "hang", "hangs", "hung", "hanging"})
_STICKING = frozenset({"stick", "sticks", "stuck", "sticking", "keep", "keeps", "kept", "keeping",
                       "stay", "stays", "stayed", "staying"})


def held_on_to(s: Sentence, at: int) -> bool:
    """Whether "to" at `at` follows a verb of holding on ("cling to", "hang on to", "holding onto",
    "stick close to")."""
    if at < 1 or s.low[at] not in ("to", "onto"):
        return False
    before = s.low[at - 1]
    if before in _CLINGING or verb_lemma(before) == "cling":
        return True
    if s.low[at] == "onto" and (before in _HOLDING_ON or before in _CLINGING):
        return True  # "holding onto the rail"
    j = at - 1 - (before in ("tight", "tightly"))  # "holds on tight to the rail"
    if j >= 1 and s.low[j] in ("on", "tight", "tightly") and s.low[j - 1] in _HOLDING_ON | _CLINGING:
        return True  # "hangs on to the rail", "clings tight to the barrier"
    return at >= 2 and before == "close" and s.low[at - 2] in _STICKING  # "stick close to the wall"
