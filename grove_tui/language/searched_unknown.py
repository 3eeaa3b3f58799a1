"""A place the world lacks, searched for by its kind (round 31): "wander off hunting for a bar", "leave
the café looking for a cashpoint", "set off in search of a vending machine". Searching for "a" kind of
place the world has no place of is a place the sentence asks for that the world cannot give: it is
refused by name, as "head for the library" is when the world has none. Only kinds of place are read
(a bar, a cashpoint, a loo), never a thing searched for ("looking for a spare trolley").

Round 53: a room searched for by name ("drift out of the gallery looking for the book room", "searching for
the quiet lounge"): "the" and a name whose last word is a word of a room (room, office, lounge, studio ...)
that no place of the world is called is refused the same way. A room the world has, under any alias, is
left to the reader.

Round 70: a kind of place searched for with "the" in one word ("in search of the café", "looking for the
lifts") that the world has no place called is refused the same way: a place sought is still a place said.

Round 72: a kind of room said with a hyphened word before a room's word ("in search of a multi-faith room",
"looking for a first-aid room") is a kind of place too, refused when the world has no place of that name."""

from __future__ import annotations

import re
from collections.abc import Sequence

from grove_tui.language.places import PlaceIndex
from grove_tui.language.tokens import phrase_lemmas

# Kinds of place people go looking for.
PLACE_KINDS = frozenset(
    "bar pub cashpoint atm cash_machine vending_machine toilet toilets loo loos lavatory gents ladies restroom restrooms "
    "cafe café canteen coffee_shop snack_bar pharmacy chemist shop newsagent kiosk lift lifts library gym chapel "
    "smoking_area first_aid_room water_fountain payphone cloakroom lockers charging_point baby_change prayer_room "
    "restaurant exit quiet_room ticket_office information_desk help_desk taxi_rank bus_stop car_park".split())
# Last words of a room's name, searched for with "the".
ROOM_HEADS = frozenset("room office lounge studio store hall suite gallery library workshop kitchen bar cafe café "
                       "canteen lab laboratory chapel gym annexe annex".split())
_SEARCH = re.compile(r"\b(?:(?:hunt|search|look|scout|seek|scour|forag|cast)(?:s|es|ed|ing)?(?:\s+(?:around|about|"
                     r"everywhere|high\s+and\s+low|round))?\s+for|in\s+search\s+of|on\s+the\s+(?:hunt|lookout)\s+for|"
                     r"(?:trying|hoping|wanting)\s+to\s+find|seeking)\s+(?P<det>a|an|some|another|the)\s+((?:[\w'-]+\s*){1,3})",
                     re.I)


def searched_unknown(prompt: str, index: PlaceIndex) -> list[str]:
    """The kinds of place (or, after "the", the rooms by name) a prompt searches for that the world has no
    place of, as written."""
    found: list[str] = []
    for m in _SEARCH.finditer(prompt):
        words = [w.strip(".,;:!?").lower() for w in m.group(2).split()]
        by_name = m.group("det").lower() == "the"
        for end in (range(min(3, len(words)), 0, -1) if by_name else (2, 1)):
            phrase = words[:end]
            if by_name and end == 1 and phrase[0] not in PLACE_KINDS:
                continue  # "in search of the café": one word, a kind of place; "the office" alone is no name
            if by_name and end > 1 and (phrase[-1] not in ROOM_HEADS or not all(w.isalpha() for w in phrase)):
                continue
            hyphened_room = (not by_name and end == 2 and len(phrase) == 2 and phrase[1] in ROOM_HEADS
                             and re.fullmatch(r"[a-z]+(?:-[a-z]+)+", phrase[0]) is not None)
            if not by_name and not hyphened_room and (len(phrase) < end or "_".join(phrase) not in PLACE_KINDS):
                continue
            said = " ".join(phrase)
            if hyphened_room:
                phrase = [*phrase[0].split("-"), phrase[1]]
            match = index.match(phrase_lemmas(phrase) if by_name else phrase)
            if match is None or not match.exact:
                found.append(said)
            break
    return found
