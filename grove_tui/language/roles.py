"""Pass 5, part 1: the role each place phrase plays for a group (start, destination, location, via),
from its preposition or verb, the group's intent and where the phrase stands against the verb:
"from X": start; "to X": destination; "at X" for people who stay: location, for movers the start
("the patients in ward A walk to ..."), or the destination of a verb of arrival ("arrive at X");
"through X": via, or the destination when X is an exit they leave by."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field, replace

from grove_tui.language import lexicon as lx
from grove_tui.language.descriptor_starts import start_said_after
from grove_tui.language.exercise_machines import stays_on_a_machine
from grove_tui.language.later_stops import goes_on_after
from grove_tui.language.place_narrowing import guessed_over_named
from grove_tui.language.place_phrases import Place
from grove_tui.language.numbered_things import named_by_number
from grove_tui.language.places import PlaceIndex, PlaceMatch
from grove_tui.language.surging_across import crosses_from
from grove_tui.language.tokens import phrase_lemmas, verb_lemma
from grove_tui.language.worked_things import room_worked_in


@dataclass
class Roles:
    """A group's places by role, and the phrase each place was read from."""

    start: str | None = None
    destination: str | None = None
    location: str | None = None
    via: list[str] = field(default_factory=list)
    read_from: dict[str, Place] = field(default_factory=dict)


def assign_roles(index: PlaceIndex, places: Sequence[Place], scene_places: Sequence[Place], *, verb: str,
                 verb_index: int | None, stationary: bool, intent: str, then_at: Sequence[int] = (),
                 verbs_at: Sequence[tuple[int, str]] = (), moves_at: Sequence[int] = (),
                 stayed_at: frozenset[int] = frozenset()) -> Roles:
    """The group's places by role: a narrower place (a fixture of the zone already read) replaces
    the zone; a destination said with "to" is not replaced by a later "at"; a place they stay at
    after "then" is where they stay, the one before it where they start ("buys a paper at the
    newsagent, then waits in the waiting room"); a room or thing a verb acts on before they set off
    (`moves_at`: where the clause's verbs of walking are) is where they start ("locks her office and
    leaves by the back door")."""
    roles = Roles()
    said_to = False  # the destination came with "to", "into" ...: a later "at" does not replace it
    said = [p for p in places if p.match is not None and p.prep != "obj:seen"]
    landmarks = _landmarks(places)
    for p in [*places, *scene_places]:
        if p.match is None or (p.prep == "obj:seen" and said) or p in landmarks:
            continue  # "watch TV in the lounge": they are in the lounge
        name = p.match.name
        roles.read_from.setdefault(name, p)
        # a door's role follows the verb that governs it ("drops a parcel at reception and leaves by the
        # main door": leaving, though the clause's verb is dropping off)
        own_verb = next((v for i, v in reversed(verbs_at) if i < p.index), verb) if p.match.kind == "door" else verb
        role = role_of(index, p, own_verb, verb_index, stationary, intent, p in scene_places)
        role = "location" if role == "start" and stays_on_a_machine(p, own_verb, places) else role
        if role == "destination" and p in scene_places and roles.destination is not None and p not in places:
            role = "start"  # "smoke drifts into Gallery 3 and the visitors leave by the fire door": the door
        if role in ("start", "via") and p in scene_places and (roles.start or roles.location):
            continue  # "a fire breaks out in radiology: ... visitors in the cafeteria": where they are is their own
        if role == "start" and p in scene_places and p.match.kind == "entity" and p.match.zone and \
                (intent == "evacuate" or p.prep not in ("in", "inside")) and \
                not (intent != "evacuate" and p.index in stayed_at) and \
                not (intent != "evacuate" and named_by_number(index, p.match, p.words)):  # "After ten minutes in the sauna", "on the chairs"
            name = p.match.zone  # "smoke pours from the star projector and the audience flee": from its room
            roles.read_from.setdefault(name, p)
        if role == "via" and p.prep == "obj:at" and roles.start is None and any(v > p.index for v in moves_at):
            role = "start"  # "locks her office and leaves", "tidies her desk, then walks to ...": where they set off
        marked = p.prep in lx.DESTINATION_PREPOSITIONS or p.prep == "obj:dest"
        leaving = role == "destination" and own_verb in lx.DEPARTURE_VERBS and p.match.kind == "door"
        if (p.sequel or leaving) and role == "destination" and roles.destination is not None and name not in roles.via \
                and roles.destination != name:
            # "drops a parcel at reception and leaves by the main door": reception on the way out
            # "to the café and then the pharmacy": the café on the way, the pharmacy where they end
            roles.via.append(roles.destination)
            roles.destination = name
        elif role == "destination" and marked and said_to and roles.destination not in (None, name) and \
                name not in roles.via and (gone := roles.read_from.get(roles.destination)) is not None and \
                goes_on_after(list(then_at), gone.index, p.index):
            # "walk to the cafeteria before going to the pharmacy": the cafeteria on the way
            roles.via.append(roles.destination)
            roles.destination = name
        elif role == "start" and (roles.start is None or _narrows(index, name, roles.start, roles) or
                                  start_said_after(roles.read_from.get(roles.start), p, verb_index)):
            roles.start = name  # "tourists off the coaches stream from the coach park": from the park
        elif role == "destination" and (roles.destination is None or _narrows(index, name, roles.destination, roles)
                                        or (marked and not said_to)):
            # "drops her bags off at the lockers and heads to the café": the café
            roles.destination, said_to = name, said_to or marked
        elif role == "location" and roles.location is not None and \
                room_worked_in(index, roles.read_from.get(roles.location), p) is not None:
            roles.location = name  # "folds tunics in the kit room": the room they work in
        elif role == "location" and (roles.location is None or _narrows(index, name, roles.location, roles)):
            roles.location = name
        elif role in ("location", "destination", "start") and getattr(roles, role) is not None and \
                p not in scene_places and (inside := _fixture_inside(index, getattr(roles, role), p, roles)) is not None:
            setattr(roles, role, inside)  # "on a bench in the modern art gallery": that gallery's bench
        elif role == "location" and roles.start is None and roles.location is not None and name != roles.location and \
                any(roles.read_from[roles.location].index < t < p.index for t in then_at):
            roles.start, roles.location = roles.location, name
        elif role == "via" and name not in roles.via:
            roles.via.append(name)
    taken = next((p.match.name for p in places if p.prep == "obj:via" and p.match is not None
                  and verb_lemma(p.written) == "take" and p.match.name in roles.via), None)
    if taken is not None and roles.destination is None and not stationary:
        # "five visitors take the stairs": with nowhere else to go, the way they take is where they go
        roles.via.remove(taken)
        roles.destination = taken
    if intent == "wander" and roles.destination is not None and roles.start is None and roles.location is not None \
            and roles.read_from[roles.location].prep == "from":
        roles.start, roles.location = roles.location, None  # "wander from the paint aisle over to lighting"
    if roles.via and roles.destination is None and roles.start is not None and not stationary and \
            _leads_out(index, roles.via[-1]):
        # "trail out of the departure lounge and down the forward gangway": a way out of the building
        # said last, with nowhere else to go, is where they end
        roles.destination = roles.via.pop()
    return roles


def _leads_out(index: PlaceIndex, name: str) -> bool:
    """Whether a place is a door that leads out of the building (a gangway, a jet bridge, a street door)."""
    entry = index.entry(name)
    if entry is None or entry.kind != "door":
        return False
    door = index.world.find(name)
    return getattr(door, "leads_to", "") == "outside"


# Words that place a place by another: said right after a place phrase ("the study room next to the
# café", "the exit near the lifts"), the other place says where the first is, not where anyone starts.
_BESIDE = frozenset("next beside near opposite behind alongside facing".split())


def _landmarks(places: Sequence[Place]) -> list[Place]:
    """The phrases that only say where the place before them is: right after it, by a word of nearness,
    and not a fixture of its room ("sits in the café next to the window" is at the window)."""
    out = []
    for before, p in zip(places, places[1:]):
        if p.written in _BESIDE and p.index == before.end and before.match is not None and p.match is not None \
                and not (before.match.kind == "zone" and p.match.zone == before.match.name):
            out.append(p)
    return out


def narrower(index: PlaceIndex, name: str, than: str) -> bool:
    """Whether `name` is a door or thing inside the zone `than` ("the coffee machine in the kitchen")."""
    entry = index.entry(name)
    return entry is not None and entry.kind != "zone" and entry.zone == than


def _narrows(index: PlaceIndex, name: str, than: str, roles: Roles) -> bool:
    """Whether `name` is a fixture inside the place `than` was read as, or inside one of the places
    its phrase fitted as well: "in the vast hall under the departures board" is the hall with the
    board, whichever hall the words alone chose."""
    if guessed_over_named(roles.read_from.get(name), roles.read_from.get(than)):
        return False  # "from the lobby ... pay in a cheque": the lobby, not a machine guessed from "cheque"
    if guessed_over_named(roles.read_from.get(than), roles.read_from.get(name)):
        return True  # "in a wheelchair from rinkside": rinkside, not its seating guessed from "chair"
    if narrower(index, name, than):
        return True
    entry = index.entry(name)
    said = roles.read_from.get(than)
    return entry is not None and entry.kind != "zone" and said is not None and said.score < 1.0 and \
        entry.zone in said.alternatives


def _fixture_inside(index: PlaceIndex, current: str, room: Place, roles: Roles) -> str | None:
    """A fixture said, then the room it is in ("a bench in the modern art gallery"): the fixture of
    that room its words name, when the words chose one in another room; the room itself when none
    there fits and the words were not sure. None when nothing changes."""
    zone = room.match.name if room.match is not None else ""
    here, there = index.entry(current), index.entry(zone)
    said = roles.read_from.get(current)
    if here is None or there is None or said is None or here.kind == "zone" or there.kind != "zone" or \
            here.zone == there.name or room.index < said.index:
        return None
    content = {t for t in phrase_lemmas(list(said.words)) if t not in lx.DETERMINERS}
    fits = [e for e in index.entries if e.kind == here.kind and e.zone == there.name and content and content <= e.tokens]
    if fits:
        e = fits[0]
        roles.read_from[e.name] = replace(said, match=PlaceMatch(e.name, e.kind, e.zone, 1.0, False), score=0.8,
                                          alternatives=(), reason=f"'{' '.join(said.words)}' in {zone}: {e.name}")
        return e.name
    return zone if said.score < 1.0 else None


def role_of(index: PlaceIndex, p: Place, verb: str, verb_index: int | None, stationary: bool, intent: str,
            from_scene: bool) -> str:
    prep = p.prep
    is_door = p.match is not None and p.match.kind == "door"
    if prep == "out":
        return "destination" if is_door else "start"
    if prep == "from" and p.out_of and is_door and _is_exit(index, p) and verb not in lx.ARRIVAL_VERBS:
        return "destination"  # "run out of the north doors": out of the building through them
    if prep == "from" and p.written == "from" and stationary and intent in lx.STATIONARY_INTENTS and \
            (verb_index is None or p.index > verb_index):  # not a fronted "From the pharmacy, two wait"
        return "location"  # "a guard watches them from the supermarket doors": where the watcher stands
    if prep in ("from", "obj:start") or prep == "off" and not stationary:
        return "start"  # "brings the washing in off the balcony": off it is where they set out (round 69)
    if prep in ("for", "purpose"):  # "head for the exit"; "to catch the train at platform 1"
        return "location" if stationary else "destination"
    if prep in ("to", "into", "towards", "toward", "onto", "obj:dest"):
        return "destination"
    if prep == "obj:via":
        return "via"
    if prep == "between" and not stationary:
        return "destination" if p.sequel else "start"  # "walks between ward A and ward B": from one to the other
    if prep in lx.VIA_PREPOSITIONS:
        return _through(index, p, verb, stationary, intent, is_door)
    if prep == "by" and is_door and (verb in lx.DEPARTURE_VERBS | lx.BOARDING_VERBS or intent == "evacuate"):
        return "destination"
    if prep == "by" and is_door and verb in lx.ARRIVAL_VERBS and _is_exit(index, p):
        return "start"  # "arrive by the side entrance": in from outside
    if prep == "obj:at":
        return "location" if stationary else "via"
    if prep == "obj:seen":
        return "location"
    # at / in / on / near / around ...
    if stationary:
        return "location"
    if intent == "robot" and not from_scene and (verb_index is None or p.index > verb_index):
        return "location"  # "runs up to the robot beside the kiosk": where they meet it
    if from_scene or verb_index is None or p.index < verb_index:
        return "start"
    return "destination" if verb in lx.ARRIVAL_VERBS else "start"


def _through(index: PlaceIndex, p: Place, verb: str, stationary: bool, intent: str, is_door: bool) -> str:
    if stationary and not is_door:
        return "location"  # "pace up and down the corridor", "wander through the concourse"
    if is_door and (verb in lx.DEPARTURE_VERBS | lx.BOARDING_VERBS | {"evacuate"} or intent == "evacuate"):
        # "leave through the side door", "board through the jet bridge": out of the scene there
        return "destination"
    if not is_door and crosses_from(verb, p.prep):
        return "start"  # "commuters surge across the station hall towards the barriers": they fill it
    entry = index.entry(p.match.name) if is_door and p.match is not None else None
    if entry is not None and entry.exit and verb not in lx.ARRIVAL_VERBS:
        return "destination"  # "go home through the back door": out of an exit is where they end
    if is_door and verb in lx.ARRIVAL_VERBS:
        return "start"
    return "via"


def _is_exit(index: PlaceIndex, p: Place) -> bool:
    entry = index.entry(p.match.name) if p.match is not None else None
    return entry is not None and entry.exit
