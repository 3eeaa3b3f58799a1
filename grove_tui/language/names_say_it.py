"""A place said by what is done there, whose words the names of one room say together (round 50): "to
where the returns get processed" is the room called "returns room" and "processing room", though by
meaning a "returns slot" elsewhere comes nearer. When every content word of the activity (two at the
least) is in the names of one zone (its own or its fixtures'), and of no other zone, that zone is where
it is done: words the world itself names the room by beat a phrase only near in meaning."""

from __future__ import annotations

import re

from grove_tui.language.places import PlaceIndex, PlaceMatch

Decided = tuple[PlaceMatch, float, str, tuple[str, ...]]

_NOT_CONTENT = frozenset("where you people they we someone somebody one who that which the a an their your his her "
                         "its our in on at to of for and or is are be get gets got do does go can could will would "
                         "some there this these those them it".split())


def _stem(word: str) -> str:
    """A word without its ending, loosely: "processing", "processed", "process" and "processes" alike."""
    if word.endswith("ies") and len(word) > 4:
        return word[:-3] + "y"  # "deliveries": "delivery"
    for suffix in ("ing", "ed", "es", "s"):
        if word.endswith(suffix) and len(word) - len(suffix) >= 3 and not word.endswith("ss"):
            word = word[:-len(suffix)]
            break
    return word[:-1] if word[-1:] in ("e", "s") and len(word) > 3 else word


def _stems(text: str) -> set[str]:
    return {_stem(w) for w in re.findall(r"[a-z]+", text.lower()) if w not in _NOT_CONTENT}


def named_by_its_words(index: PlaceIndex, activity: str) -> Decided | None:
    """The one zone whose names (and its fixtures') hold every content word of the activity, module doc."""
    content = _stems(activity)
    if len(content) < 2:
        return None
    names: dict[str, set[str]] = {}
    for e in index.entries:
        if e.kind == "door":
            continue
        for said in e.said[:1] + e.said[2:] if e.kind == "zone" else e.said:  # not the zone's type
            names.setdefault(e.zone, set()).update(_stems(said))
    zones = [z for z, words in names.items() if content <= words]
    if len(zones) != 1 or (entry := index.entry(zones[0])) is None:
        return None
    return (PlaceMatch(entry.name, entry.kind, entry.zone, 1.0, False), 0.6,
            f"'{activity}' is said by {entry.name}'s own names", ())
