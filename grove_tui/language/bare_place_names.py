"""Places people name without an article, whose first word is a participle (round 44): "walks to lost
property", "leaves the lounge for lost property", "heads over to left luggage". The parser takes
"to lost" for an infinitive and "lost" for a verb, so no place phrase was read, and a world without
a lost-property office took the sentence without a word. Said so, they are places: read as any place
phrase, matched when the world has them and refused when it does not."""

from __future__ import annotations

from collections.abc import Sequence

# Names of services that are rooms, said bare, that start with a participle or an adjective the
# parser takes for a verb.
BARE_PLACE_NAMES: tuple[tuple[str, ...], ...] = (
    ("lost", "property"), ("lost", "and", "found"), ("left", "luggage"), ("left", "-", "luggage"),
    ("lost", "luggage"), ("lost", "children"),
)


def bare_place_name(low: Sequence[str], k: int) -> int:
    """The number of words of such a name starting at k ("lost property": 2), or 0."""
    for name in BARE_PLACE_NAMES:
        if tuple(low[k:k + len(name)]) == name and (k + len(name) >= len(low) or low[k + len(name)] not in _PEOPLE):
            return len(name)
    return 0


# Words after "lost children" that make it the children, not the place ("lost children wander about").
_PEOPLE = frozenset({"wander", "wanders", "cry", "cries", "are", "were", "who", "wait", "waiting"})
