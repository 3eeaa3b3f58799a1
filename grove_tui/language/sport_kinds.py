"""Named kinds of room for sport and exercise ("the sports hall", "the gym", "the swimming pool"): a
kind of place of its own, refused in a world that has none (language/place_kinds.py), though a room
there is used for sport-like things or shares the head word ("the main hall", "hall"). A world's name
as near as a synonym counts only when it is more than the kind's head word: "hall" is no sports hall."""

from __future__ import annotations

from grove_tui.language.tokens import name_tokens

SPORT_KINDS = frozenset("""
sport_hall gym gymnasium fitness_suite fitness_room weight_room weights_room
swimming_pool swimming_bath squash_court badminton_court tennis_court climbing_wall
""".split())


def only_the_head(kind: str, nearest: str) -> bool:
    """Whether the world's nearest name is no more than the kind's last word ("hall" of "sport hall")."""
    parts = kind.split("_")
    return len(parts) > 1 and name_tokens(nearest) == parts[-1:]
