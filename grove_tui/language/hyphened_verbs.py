"""A verb written as two words joined by a hyphen (round 69): "keen to test-drive the estate car", "to
spot-check the tills", "to deep-clean the fryers". The parser reads the first word as a noun ("test"),
so the "to" before it read as a way to a place, and the purpose was lost (or refused as a place). When
the word after the hyphen is a verb in its base form, the whole is the verb: what follows "to" is a
purpose (sentence.py, verb_follows)."""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from grove_tui.language.sentence import Sentence


def hyphened_verb(s: Sentence, k: int) -> bool:
    """Whether the words from k are a verb written with a hyphen ("test-drive", "spot-check")."""
    return k + 2 < s.n and s.low[k + 1] == "-" and s.hyphen_inside(k + 1) and s.low[k].isalpha() and \
        s.w[k + 2].tag == "VB" and k > 0 and s.low[k - 1] == "to"
