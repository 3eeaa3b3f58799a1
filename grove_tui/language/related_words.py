"""Words that say one activity or one kind of place in other words, for a place said by what is done there:
"where the clay gets fired" is the craft room ("where the pottery classes are held ... and the kiln"),
"wherever the paintings are kept in storage" the art store ("where pictures not on show hang"), "where
the sheets get laundered" the laundry. A word of the clause is said by a room's description when the
description has the word or one of its family here; each family is one activity, its things and its
room, never words that only sit near each other."""

from __future__ import annotations

from collections.abc import Callable, Iterable
from functools import lru_cache

_FAMILIES: tuple[tuple[str, ...], ...] = (
    ("clay", "pottery", "potter", "ceramic", "ceramics", "kiln", "glaze", "glazing"),
    ("fire", "fired", "firing", "kiln", "kilns"),
    ("bake", "baked", "baking", "oven", "ovens", "bakery"),
    ("paint", "painting", "paintings", "picture", "pictures", "artwork", "artworks", "canvas", "canvases"),
    ("store", "stored", "storage", "storeroom", "kept", "keep", "stow", "stowed", "stock"),
    ("patch", "patched", "treat", "treated", "treatment", "bandage", "bandaged", "injury", "injured", "hurt",
     "wound", "wounded", "first-aid", "aid", "medical", "sick", "stitch", "stitched"),
    ("wash", "washed", "washing", "launder", "laundered", "laundry", "washer", "washers", "dryer"),
    ("cook", "cooked", "cooking", "kitchen", "chef", "chefs", "stove", "hob"),
    ("eat", "eaten", "meal", "meals", "dining", "dine", "lunch", "dinner", "canteen", "cafeteria"),
    ("sleep", "slept", "sleeping", "bed", "beds", "bunk", "bunks", "dorm", "dormitory", "bedroom", "nap"),
    ("repair", "repaired", "mend", "mended", "fix", "fixed", "workshop", "maintenance", "serviced"),
    ("rent", "rented", "rental", "hire", "hired"),
    ("pray", "prayed", "prayer", "prayers", "worship", "chapel", "faith"),
    ("filter", "filtered", "filtration", "filters", "purified"),
    ("lesson", "lessons", "class", "classes", "taught", "teach", "classroom"),
    ("mail", "post", "posted", "parcel", "parcels", "letter", "letters", "sorted"),
)


@lru_cache(maxsize=8)
def _stemmed(stem: Callable[[str], str]) -> tuple[frozenset[str], ...]:
    return tuple(frozenset(stem(w) for w in family) for family in _FAMILIES)


def widened(said: Iterable[str], stem: Callable[[str], str]) -> set[str]:
    """The stems `said` (a description's) with the stems of every family one of them is in."""
    have = set(said)
    out = set(have)
    for family in _stemmed(stem):
        if family & have:
            out |= family
    return out


def said_in(stem: str, said: set[str]) -> bool:
    """Whether a clause's stem is said by a description's stems (widened): itself, or a doer of a thing
    said ("skiers" where the description says "ski")."""
    return stem in said or (stem.endswith("er") and len(stem) > 4 and stem[:-2] in said)


def to_another_where(low: list[str], at: int) -> bool:
    """Whether the word at `at` starts a second place said by what is done there, which ends a clause:
    "from where people rent skis | to where injured skiers get patched up"."""
    return at + 1 < len(low) and low[at] in ("to", "into", "towards", "toward") and \
        low[at + 1] in ("where", "wherever")
