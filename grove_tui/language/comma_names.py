"""A place whose name is a list, said with its commas (round 44): "four rise and stroll through to births,
deaths and marriages" where the world calls the register office "births deaths and marriages". Split at
its commas, the name's first word was refused as a place the world lacks ("births") and the walk had no
destination. A run of words that is one of the world's names of three words or more once its commas are
left out is written without them before the sentence is parsed, and read as that name."""

from __future__ import annotations

import re
from functools import lru_cache
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from grove_tui.language.places import PlaceIndex


@lru_cache(maxsize=32)
def _listed_names(index: PlaceIndex) -> tuple[re.Pattern[str], ...]:
    """Patterns of the world's names of three words or more, with a comma allowed between any two words."""
    names = {" ".join(said.lower().replace(",", " ").split()) for e in index.entries for said in e.said}
    out = []
    for name in sorted(names, key=len, reverse=True):
        words = name.split()
        if len(words) < 3 or not all(w.replace("'", "").replace("’", "").isalpha() for w in words):
            continue
        joints = [r"\s*,\s*|\s+" for _ in words[1:]]
        body = re.escape(words[0]) + "".join(f"(?:{j}){re.escape(w)}" for j, w in zip(joints, words[1:]))
        out.append(re.compile(r"\b" + body + r"\b", re.IGNORECASE))
    return tuple(out)


def without_name_commas(text: str, index: PlaceIndex) -> str:
    """The text with the commas inside a listed name of the world left out (module doc)."""
    if "," not in text:
        return text
    for pattern in _listed_names(index):
        text = pattern.sub(lambda m: " ".join(m.group(0).replace(",", " ").split()) if "," in m.group(0) else m.group(0),
                           text)
    return text
