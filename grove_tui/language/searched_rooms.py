"""A room the world lacks, searched for by name (round 53): "drift out of the gallery looking for the
book room", "wander about searching for the quiet lounge". Searching for "the" room of some kind (its
last word a word of a room: room, office, lounge, studio, store ...) that no place of the world is
called is a place the sentence asks for that the world cannot give: refused by name, as searching for
"a bar" is (searched_unknown). A room the world has, under any alias, is left to the reader."""

from __future__ import annotations

import re

from grove_tui.language.places import PlaceIndex
from grove_tui.language.tokens import phrase_lemmas

# Last words of a room's name.
ROOM_HEADS = frozenset("room office lounge studio store hall suite gallery library workshop kitchen bar cafe café "
                       "canteen lab laboratory chapel gym annexe annex".split())
_SEARCH = re.compile(r"\b(?:(?:hunt|search|look|scout|seek|scour|cast)(?:s|es|ed|ing)?(?:\s+(?:around|about|"
                     r"everywhere|round))?\s+for|in\s+search\s+of|(?:trying|hoping|wanting)\s+to\s+find|seeking)"
                     r"\s+the\s+((?:[\w'-]+\s*){1,3})", re.I)


def searched_rooms(prompt: str, index: PlaceIndex) -> list[str]:
    """The rooms a prompt searches for by name that the world has no place called (module doc)."""
    found: list[str] = []
    for m in _SEARCH.finditer(prompt):
        words = [w.strip(".,;:!?").lower() for w in m.group(1).split()]
        for end in range(min(3, len(words)), 1, -1):
            phrase = words[:end]
            if phrase[-1] not in ROOM_HEADS or not all(w.isalpha() for w in phrase):
                continue
            match = index.match(phrase_lemmas(phrase))
            if match is None or not match.exact:
                found.append(" ".join(phrase))
            break
    return found
