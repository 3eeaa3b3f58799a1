"""A place said by what is done there, read from the one room whose description says it in its own words,
whatever the inflection: "to where the costumes get sewn" is the wardrobe ("where the costumes are cut,
sewn, fitted and mended"), not the costume rails only named like the thing done to; "where the forklifts
get repaired" is the workshop ("where forklifts ... are repaired"), not the forklift charging bay; "the
place where pregnant women have their scans" is the scan room ("for ultrasound scans").

The clause's words that say who does it ("pregnant women", "you", "staff") and its light verbs ("have",
"get") are left out; every other word must be in the description (by a rough stem: "sewn" is "sew",
"fired" is "fire"), and only one room may say them all."""

from __future__ import annotations

import re
from collections.abc import Sequence

from grove_tui.language.activity_rooms import _said_of
from grove_tui.language.lexicon import PERSON_NOUNS
from grove_tui.language.related_words import said_in, widened
from grove_tui.language.places import MeaningMatch, PlaceIndex, PlaceMatch
from grove_tui.language.tokens import lemma

# Words that say nothing of the activity: markers, pronouns, determiners, auxiliaries and light verbs.
_EMPTY = frozenset("where you people they we someone somebody one who that which whom the a an their your his her "
                   "its our my in on at to of for and or is are was were be been being get gets got gotten getting "
                   "have has had having do does did done can could will would some there all any just usually "
                   "normally often always then them it with by from up out off away down over".split())  # particles: "sorted out"
_PEOPLE = frozenset({"staff", "everyone", "everybody", "folk", "folks", "visitor", "guest"})


def _stem(word: str) -> str:
    """A rough stem, enough to match a verb's forms and a noun's number ("sewn", "sews": "sew"; "fired",
    "fire": "fir"; "scanned", "scans": "scan")."""
    w = lemma(word.lower())
    if w.endswith("wn") and len(w) > 3:
        w = w[:-1]  # "sewn", "drawn", "shown"
    for suffix in ("ing", "ed", "es", "s"):
        if w.endswith(suffix) and len(w) - len(suffix) >= 3:
            w = w[:-len(suffix)]
            break
    if w.endswith("e") and len(w) > 3:
        w = w[:-1]
    if len(w) > 3 and w[-1] == w[-2] and w[-1] not in "aeiouls":
        w = w[:-1]  # "scann" -> "scan"
    return w


def _is_person(word: str) -> bool:
    return word in _PEOPLE or lemma(word) in PERSON_NOUNS or lemma(word) in _PEOPLE


def activity_words(activity: str) -> list[str]:
    """The stems of the words that say what is done, without who does it: the people and the words just
    before them ("pregnant women"), and the empty words."""
    words = re.findall(r"[a-z]+", activity.lower())
    drop: set[int] = set()
    for i, w in enumerate(words):
        if _is_person(w):
            drop.add(i)
            x = i - 1
            while x >= 0 and i - x <= 2 and words[x] not in _EMPTY:
                drop.add(x)  # "pregnant women", "new mums"
                x -= 1
    return [_stem(w) for i, w in enumerate(words) if i not in drop and w not in _EMPTY]


def _says_all(stems: list[str], description: str) -> bool:
    said = widened({_stem(w) for w in re.findall(r"[a-z]+", description.lower())}, _stem)  # "fired": the kiln
    return bool(stems) and all(said_in(s, said) for s in stems)


def _says_literally(stems: list[str], description: str) -> bool:
    said = {_stem(w) for w in re.findall(r"[a-z]+", description.lower())}
    return bool(stems) and all(s in said for s in stems)


def zone_saying(index: PlaceIndex, activity: str, best: MeaningMatch | None) -> MeaningMatch | None:
    """The room whose description (or a fixture's in it) says every word of the activity, when it is the
    only room that does and `best` (the place read by meaning, if any) is not in it or is a fixture whose
    own description does not say it; None otherwise."""
    stems = activity_words(activity)
    if not stems:
        return None
    zones = {e.zone for e in index.entries if e.kind != "door" and e.description and _says_all(stems, e.description)}
    if len(zones) > 1:  # several only by a family's words ("post" for "sorted"): the one saying them itself
        zones = {e.zone for e in index.entries if e.zone in zones and e.kind != "door" and e.description and
                 _says_literally(stems, e.description)}
    if len(zones) != 1:
        return None
    (zone,) = zones
    room = index.entry(zone)
    if room is None or room.kind != "zone":
        return None
    if best is not None and best.entry.zone == zone and (best.entry.kind == "zone" or _said_of(
            best.entry, room.description) or _says_all(stems, best.entry.description or "")):
        return None  # already there: the room, or a fixture that says it of itself or the room says it of
    return MeaningMatch(room, best.similarity if best is not None else 0.5, room.description)


def room_doing_it(index: PlaceIndex, activity: str) -> tuple[PlaceMatch, float, str, tuple[str, ...]] | None:
    """The room only whose description says the activity, when meaning found no place: "where the clay gets
    fired" is no nearer the craft room by meaning, but one room says it."""
    found = zone_saying(index, activity, None)
    if found is None:
        return None
    e = found.entry
    return (PlaceMatch(e.name, "zone", e.zone, 0.6, False), 0.6,
            f"'{activity}' is said by the description of {e.name} only (like '{e.description[:60]}')", ())


def gerund_room(index: PlaceIndex, phrase: Sequence[str], match: PlaceMatch) -> PlaceMatch:
    """A place said by the work done there, a gerund ("head for fingerprinting", "off to scanning"): the
    room whose own names say it (the biometrics room, "fingerprint room"; the scan room), not a fixture
    read from it (the fingerprint scanners, the ultrasound machine) whose names do not hold the gerund
    itself; `match` otherwise."""
    words = [w.lower() for w in phrase if w.lower() not in _EMPTY]
    if len(words) != 1 or not words[0].endswith("ing") or len(words[0]) < 7 or match.kind != "entity":
        return match
    fixture = index.entry(match.name)
    if fixture is None or words[0] in fixture.tokens:
        return match  # "the seating": a fixture so named
    stem = _stem(words[0])
    zones = [e for e in index.entries if e.kind == "zone" and any(_stem(t) == stem for t in e.tokens)]
    own = [e for e in zones if e.name == match.zone]
    chosen = own[0] if own else zones[0] if len(zones) == 1 else None
    return PlaceMatch(chosen.name, "zone", chosen.name, match.score, False) if chosen is not None else match
