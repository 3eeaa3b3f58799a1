"""Places described by what is done there, a mixin of language/place_phrases.py beside its meaning half
(language/place_meaning.py): idioms said as the plain words the world's names and descriptions use
("pump iron" is lifting weights, "patched up" is treated), a place said only by its clause ("to where
you get your bags back", "wait where the trains come in"), and a ranking of the world's rooms by both
their names and what the world says they are (descriptions), by zone, with a margin so a poor match is
not taken.
"""

from __future__ import annotations

import re
from collections.abc import Sequence

from grove_tui.language.grooming_words import plain_grooming
from grove_tui.language.imaging_words import plain_imaging
from grove_tui.language.model import UNSURE_BELOW
from grove_tui.language.lexicon import PLACE_MODIFIERS
from grove_tui.language.names_say_it import named_by_its_words
from grove_tui.language.places import PlaceIndex, PlaceMatch
from grove_tui.language.tokens import lemma, phrase_lemmas, verb_lemma

Decided = tuple[PlaceMatch, float, str, tuple[str, ...]]

# Idioms for what people do at a place, as the plain words names and descriptions use. Each is a kind of
# activity, not a sentence: the verb phrase and its common forms.
_IDIOMS: tuple[tuple[str, str], ...] = (
    (r"pump(?:s|ed|ing)? iron", "lift weights"),
    (r"work(?:s|ed|ing)? out", "exercise in the gym"),
    (r"(?:get|gets|got|getting) patched up", "get first aid treatment"),
    (r"patch(?:es|ed|ing)? (?:\w+ )?up", "give first aid to"),
    (r"(?:get|gets|got|getting) stitched up", "get first aid treatment"),
    (r"(?:do|does|did|doing) (?:their |your |some )?lengths", "swim in the pool"),
    (r"shoot(?:s|ing)? hoops", "play basketball"),
    (r"hit(?:s|ting)? the books", "study"),
    (r"grab(?:s|bed|bing)? a bite", "eat food"),
    (r"(?:get|gets|got|getting) (?:their |your )?(?:bags|luggage|suitcases) back", "reclaim baggage"),
    (r"freshen(?:s|ed|ing)? up", "use the toilets"),
    (r"spend(?:s|ing)? a penny", "use the toilets"),
    (r"(?:get|gets|got|getting) changed", "use the changing rooms"),
    (r"(?:get|gets|got|getting) (?:their |your )?(?:hair )?(?:cut|trimmed)", "have a haircut at the hairdresser"),
    (r"catch(?:es|ing)? some rays", "sit in the sun outside"),
)
# Where a vehicle comes in or leaves from is its stop: "where the trains come in" is a platform.
_VEHICLE_STOPS = {"train": "platform", "trains": "platform", "tube": "platform", "tram": "platform",
                  "trams": "platform", "plane": "gate", "planes": "gate", "flight": "gate", "flights": "gate",
                  "bus": "bus stop", "buses": "bus stop", "coach": "coach bay", "coaches": "coach bay",
                  "taxi": "taxi rank", "taxis": "taxi rank", "cab": "taxi rank", "cabs": "taxi rank",
                  "lift": "lift lobby", "lifts": "lift lobby", "ferry": "pier", "boat": "pier", "boats": "pier"}
_COMING = re.compile(r"\b(?:the |a )?(\w+) (?:come|comes|came|pull|pulls|get|gets|arrive|arrives|leave|leaves|"
                     r"depart|departs|stop|stops|go|goes)\b")

# A place ranked by names and descriptions: this near at the least, and this far ahead of any other zone.
DESCRIBED_ACCEPT = 0.4
DESCRIBED_MARGIN = 0.05


# A description that says the activity in its own words ("students come to its counter to hand in
# coursework") is where it is done, more surely than a name only near it in meaning ("lecturers' office").
DESCRIPTION_SAYS_IT = 0.08
_NOT_CONTENT = frozenset("where you people they we someone somebody one who that which the a an their your his her "
                         "its our in on at to of for and or is are be get do go can could will would some "
                         "there".split())


def content_words(activity: str) -> set[str]:
    """The activity's own words, as lemmas: "where you develop film" is {"develop", "film"}."""
    return {verb_lemma(lemma(w)) for w in re.findall(r"[a-z]+", activity.lower()) if w not in _NOT_CONTENT}


def says_it(activity: str, description: str) -> float:
    """The bonus of a description holding the activity's own words: at least two of them, or all."""
    if not description:
        return 0.0
    content = content_words(activity)
    said = {verb_lemma(lemma(w)) for w in re.findall(r"[a-z]+", description.lower())}
    shared = len(content & said)
    return DESCRIPTION_SAYS_IT if content and (shared >= 2 or shared == len(content)) else 0.0


def plain_activity(activity: str) -> str:
    """The activity in plain words: its idioms replaced ("where people pump iron": "where people lift
    weights"), a vehicle's coming or going said as its stop ("where the trains come in": "the platform
    where the trains come in")."""
    said = activity.lower()
    for pattern, plain in _IDIOMS:
        said = re.sub(r"\b" + pattern + r"\b", plain, said)
    return plain_imaging(plain_grooming(said))  # "get powdered", "pictures of your teeth"


def vehicle_stop(activity: str) -> str | None:
    """The stop of a vehicle said coming or going ("where the trains come in": "platform")."""
    found = _COMING.search(activity.lower())
    return _VEHICLE_STOPS.get(found.group(1)) if found is not None else None


def rank_described(index: PlaceIndex, activity: str, kinds: Sequence[str] | None = None,
                   accept: float = DESCRIBED_ACCEPT) -> Decided | None:
    """The room (or fixture) an activity is done at, by its names and its description together: each
    zone is as near as its nearest name or description, or one of its fixtures'; the nearest zone is
    taken when near enough and clearly ahead of the next; the fixture when it is the nearest of its
    zone's and the head allows fixtures (`kinds`: the places the phrase's head can be, all when None)."""
    if kinds is None and (named := named_by_its_words(index, activity)) is not None:
        return named  # "where the returns get processed": the "returns room", the "processing room"
    stop = vehicle_stop(activity)
    stops = [e.name for e in index.entries
             if stop is not None and e.kind != "door" and set(stop.split()) <= set(e.phrases[0])]
    allowed = set(kinds) & set(stops) if kinds is not None and stops else set(stops) if stops else \
        set(kinds) if kinds is not None else None
    best_of: dict[str, tuple[float, str, str]] = {}  # zone -> (similarity, place, like)
    for ranked in (index.by_meaning(activity), index.by_description(activity)):
        for r in ranked:
            e = r.entry
            if e.kind == "door" or (allowed is not None and e.name not in allowed):
                continue
            similarity = r.similarity + says_it(activity, r.nearest if r.nearest == e.description else "")
            if similarity > best_of.get(e.zone, (-1.0, "", ""))[0]:
                best_of[e.zone] = (similarity, e.name, r.nearest)
    order = sorted(best_of.items(), key=lambda item: -item[1][0])
    if not order or (order[0][1][0] < accept and not stops):  # a vehicle's stop is named by its kind
        return None
    zone, (value, name, like) = order[0]
    # places alike ("the changing rooms", "the platforms") that come as near: the first, unsure, the others
    # offered; any other kind of place as near leaves it undecided
    kind_of = index.entry(zone)
    alike = [z for z, (v, _, _) in order[1:] if value - v < DESCRIBED_MARGIN and kind_of is not None and
             (alike_entry := index.entry(z)) is not None and alike_entry.types == kind_of.types]
    rest = [item for item in order[1:] if item[0] not in alike]
    margin = value - (rest[0][1][0] if rest else 0.0)
    if margin < DESCRIBED_MARGIN:
        return None
    chosen = index.entry(zone) if allowed is None or zone in allowed else index.entry(name)
    if chosen is None:
        return None
    score = 0.4 if alike else 0.6 if value >= 0.55 and margin >= 0.1 else 0.45
    others = tuple(alike[:3]) or ((rest[0][0],) if rest else ())
    return (PlaceMatch(chosen.name, chosen.kind, chosen.zone, value, False), score,
            f"'{activity}' is read by what is done there as {chosen.name} (like '{like[:60]}')",
            others if score < UNSURE_BELOW else ())


# Verbs of getting goods or a service ("to buy aspirin", "to borrow a book", "to post a parcel").
_GETTING = frozenset("buy get grab borrow post send collect pick order rent hire print fetch renew return pay "
                     "purchase".split())
PURPOSE_BY_USE = 0.45
PURPOSE_BY_USE_MARGIN = 0.06


def purpose_by_use(index: PlaceIndex, purpose: str) -> Decided | None:
    """The room that provides the goods or the service a purpose gets ("to buy aspirin and plasters":
    the pharmacy), by meaning of "the place to ..." against the world's names and descriptions, by zone:
    only for a verb of getting, near enough and clearly ahead, and unsure (a place said always wins)."""
    words = purpose.lower().replace("-", " ").split()
    while words and words[0] in ("to", "in", "order", "so", "as", "for"):
        words = words[1:]
    if len(words) < 2 or words[0] not in _GETTING:
        return None
    whole = _provided_by(index, purpose, words)
    if whole is not None or "and" not in words[2:]:
        return whole
    # "to buy plasters and paracetamol": a list of things, each asked of the places on its own; the one
    # room that clearly provides some of them, when no other thing is clearly got elsewhere
    items = " ".join(words[1:]).split(" and ")
    decided = [d for item in items if item and (d := _provided_by(index, purpose, [words[0], *item.split()]))]
    zones = {d[0].zone for d in decided}
    return decided[0] if len(zones) == 1 else None


def _provided_by(index: PlaceIndex, purpose: str, words: Sequence[str]) -> Decided | None:
    """The room that provides what the words of a purpose get, by zone, near enough and clearly ahead."""
    said = "the place to " + " ".join(words)
    best_of: dict[str, tuple[float, str, str]] = {}
    for ranked in (index.by_meaning(said), index.by_description(said)):
        for r in ranked:
            if r.entry.kind != "door" and r.similarity > best_of.get(r.entry.zone, (-1.0, "", ""))[0]:
                best_of[r.entry.zone] = (r.similarity, r.entry.name, r.nearest)
    order = sorted(best_of.items(), key=lambda item: -item[1][0])
    if not order or order[0][1][0] < PURPOSE_BY_USE:
        return None
    zone, (value, _, like) = order[0]
    other = order[1][0] if len(order) > 1 else ""
    if other and value - order[1][1][0] < PURPOSE_BY_USE_MARGIN:
        return None
    return (PlaceMatch(zone, "zone", zone, value, False), 0.45,
            f"'{purpose}' names no place; by what the world's places provide it is done at {zone} (like "
            f"'{like[:60]}')", (other,) if other else ())


def room_with(index: PlaceIndex, words: Sequence[str], j: int) -> tuple[Decided, int] | None:
    """"the room with the projector", "the place with all the treadmills" (`words`, "with" at j): the
    room the thing is in, and the index after the thing's words; None when the world has no such thing."""
    k = j + 1
    while k < len(words) and words[k] in _THING_LEADS:
        k += 1
    end = k
    while end < len(words) and end < k + 4 and words[end].isalnum() and words[end] not in _THING_ENDS:
        end += 1
    for stop in range(end, k, -1):
        lemmas = [t for t in phrase_lemmas(list(words[k:stop])) if t not in PLACE_MODIFIERS]
        found = index.match(lemmas) if lemmas else None
        if found is None and lemmas:  # "the projector": the first word of "projector screen", a thing of one room
            zones = {e.zone for e in index.entries if e.kind == "entity" and set(lemmas) <= e.tokens}
            only = zones.pop() if len(zones) == 1 else None
            found = PlaceMatch(only, "zone", only, 1.0, True) if only is not None else None
        entry = index.entry(found.name) if found is not None else None
        if found is not None and entry is not None and (found.exact or set(lemmas) <= entry.tokens):
            zone = index.entry(found.zone)
            if zone is None:
                return None
            said = " ".join(words[k:stop])
            return (PlaceMatch(zone.name, "zone", zone.name, found.score, False), 0.7,
                    f"'with {said}': the room with {found.name}, {zone.name}", ()), stop
    return None


_THING_LEADS = frozenset("the a an all some lots of loads big large huge long".split())
_THING_ENDS = frozenset("and or to in on at for where who which that then while but".split())
