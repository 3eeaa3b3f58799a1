"""A unit's short form written in capitals before a noun is an acronym, no duration (round 60): "into
Lomond for an HR briefing" (Human Resources), "a MIN report". Lower-cased, "an HR briefing" read as
"an hr", an hour's stay, and the purpose ("briefing") was lost. A unit said in capitals and followed
by a noun modifies that noun; "2 HRS at the desk" (no noun after) is still a duration."""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from grove_tui.language.sentence import Sentence


def acronym_before_noun(s: Sentence, k: int) -> bool:
    """Whether word k is written in capitals (two letters or more) and a noun follows it."""
    text = s.w[k].text
    return len(text) >= 2 and text.isalpha() and text.isupper() and k + 1 < s.n and \
        s.w[k + 1].pos in ("NOUN", "PROPN") and s.w[k + 1].text.isalpha() and not s.w[k + 1].text.isupper()
