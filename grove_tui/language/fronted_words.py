"""A word fronted before a named subject (round 30): "Intrigued, Dorothy shuffles across the lounge",
"Terrified, Oliver scurries away from the robot". The fronted participle says how the person feels;
it is no verb of the sentence's, so the "-s" word after the name is still the name's own verb."""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from grove_tui.language.parser import Word


def fronted_only(words: list[Word], k: int) -> bool:
    """Whether the only verbs before word k in its sentence are one fronted word set off by a comma
    ("Intrigued, Dorothy shuffles": "Intrigued" then ",", then the subject)."""
    sentence = [j for j in range(k) if words[j].sentence == words[k].sentence]
    verbs = [j for j in sentence if words[j].pos in ("VERB", "AUX")]
    if len(verbs) != 1 or not sentence:
        return False
    first = sentence[0]
    return verbs[0] == first and first + 1 < k and words[first + 1].lower == "," and \
        words[first].lower.endswith(("ed", "ing")) and words[first].tag in ("VBN", "VBG", "VBD")
