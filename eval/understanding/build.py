"""Build the public understanding suite: sentence templates x phrasings x every shipped world.

    python eval/understanding/build.py            # writes eval/understanding/cases.yaml
    python eval/understanding/build.py --check    # exits 1 when cases.yaml is not what this script builds

Every case's expected reading follows from the slots the template was filled with, never from
running the reader: a template that writes "{count} {who} wait in the {zone} for {duration}"
knows the count, the intent, the location and the seconds it wrote. Places come from each
world's own zones, doors and entities, spoken either by their name (underscores as spaces) or by
one of their aliases, and only in forms that name exactly one place of that world (an alias two
places share could not have one expected answer).

The build is deterministic: each (world, class) pair draws from its own `random.Random` seeded
with a string, which Python hashes with SHA-512, so the file is the same on every machine.
"""

from __future__ import annotations

import argparse
import math
import random
import re
import sys
from dataclasses import dataclass, field
from pathlib import Path

import yaml

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parents[1]))  # run from a checkout without installing

from grove_tui.world import World, load_world  # noqa: E402

WORLDS = ("hospital", "office", "residential", "airport")

# Who is in each world: (plural, singular). Generic nouns are added to every world.
PEOPLE: dict[str, list[tuple[str, str]]] = {
    "hospital": [("patients", "patient"), ("visitors", "visitor"), ("nurses", "nurse"), ("doctors", "doctor")],
    "office": [("employees", "employee"), ("colleagues", "colleague"), ("visitors", "visitor"),
               ("engineers", "engineer")],
    "residential": [("children", "child"), ("guests", "guest"), ("residents", "resident"), ("friends", "friend")],
    "airport": [("passengers", "passenger"), ("travellers", "traveller"), ("tourists", "tourist"),
                ("pilots", "pilot"), ("flight attendants", "flight attendant")],
}
GENERIC_PEOPLE = [("people", "person"), ("students", "student"), ("men", "man"), ("women", "woman")]

# Largest head count a template writes for one group, by world size (a flat of 170 m2 holds few).
MAX_COUNT = {"hospital": 25, "office": 15, "residential": 5, "airport": 30}

NUMBER_WORDS = ["zero", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine", "ten",
                "eleven", "twelve", "thirteen", "fourteen", "fifteen", "sixteen", "seventeen", "eighteen",
                "nineteen", "twenty"]
TENS = {20: "twenty", 30: "thirty", 40: "forty"}

# Vague quantifiers and the head counts a sensible reader may choose for them (inclusive).
VAGUE = [("a few", 2, 5), ("several", 3, 8), ("some", 2, 8), ("a handful of", 2, 6), ("a crowd of", 8, 60),
         ("many", 5, 40), ("lots of", 5, 40)]
# Approximate quantifiers: the stated number, give or take 20 %.
APPROXIMATE = ["about {n}", "around {n}", "roughly {n}", "approximately {n}", "{n} or so"]
DURATIONS = [("five minutes", 300), ("ten minutes", 600), ("two minutes", 120), ("a minute", 60),
             ("one minute", 60), ("30 seconds", 30), ("forty-five seconds", 45), ("half an hour", 1800),
             ("90 seconds", 90), ("three minutes", 180), ("20 minutes", 1200), ("a quarter of an hour", 900)]
# Purposes that are not places; the word the reading's purpose must contain.
PURPOSES = [("to register", "register"), ("to pay", "pay"), ("to ask a question", "ask"),
            ("to get a ticket", "ticket"), ("for coffee", "coffee"), ("to check in", "check"),
            ("to buy snacks", "snack"), ("to get information", "information"), ("to collect a parcel", "parcel"),
            ("for their prescriptions", "prescription"), ("to pick up keys", "key")]
# Places no shipped world has; used only where a refusal is the right answer.
FAKE_PLACES = ["helipad", "swimming pool", "ballroom", "chapel", "greenhouse", "bowling alley", "observatory",
               "library", "gymnasium", "sauna", "tennis court", "aquarium"]

ROBOT = {  # interaction -> (HuNavSim reaction, phrasings in base form)
    "look": ("Surprised", ["stare at the robot", "watch the robot", "look at the robot", "turn to look at the robot",
                           "stop and stare at the robot", "gaze at the robot"]),
    "approach": ("Curious", ["walk up to the robot", "approach the robot", "go over to the robot",
                             "come up to the robot", "move towards the robot"]),
    "follow": ("Curious", ["follow the robot", "trail behind the robot", "tag along behind the robot",
                           "follow the robot around"]),
    "avoid": ("Scared", ["avoid the robot", "keep away from the robot", "steer clear of the robot",
                         "keep their distance from the robot", "shy away from the robot"]),
    "block": ("Threatening", ["block the robot", "stand in the robot's way", "get in the robot's way",
                              "block the robot's path", "obstruct the robot"]),
}

IRREGULAR = {"have": "has", "do": "does", "go": "goes", "are": "is"}


def third_person(verb: str) -> str:
    """'walk' -> 'walks', 'hurry' -> 'hurries', 'approach' -> 'approaches' (for singular subjects)."""
    if verb in IRREGULAR:
        return IRREGULAR[verb]
    if verb.endswith(("s", "sh", "ch", "x", "z", "o")):
        return verb + "es"
    if verb.endswith("y") and verb[-2] not in "aeiou":
        return verb[:-1] + "ies"
    return verb + "s"


def conjugate(predicate: str, singular: bool) -> str:
    """Conjugate the first word of a base-form predicate; adverbs in front ("slowly make") pass."""
    if not singular:
        return predicate
    words = predicate.split(" ")
    index = 1 if words[0].endswith("ly") and len(words) > 1 else 0
    words[index] = third_person(words[index])
    return " ".join(words)


def article(word: str) -> str:
    return "an" if word[0] in "aeiou" else "a"


def number_text(n: int, rng: random.Random) -> str:
    """Digits or words, as people write them."""
    if rng.random() < 0.4:
        return str(n)
    if n < len(NUMBER_WORDS):
        return NUMBER_WORDS[n]
    tens, unit = divmod(n, 10)
    return TENS[tens * 10] + ("" if unit == 0 else "-" + NUMBER_WORDS[unit])


# --------------------------------------------------------------------------------------------- places


@dataclass(frozen=True)
class Place:
    name: str  # the world's own name: what the reading must return
    forms: tuple[str, ...]  # ways to say it that name only this place
    kind: str  # zone | door | entity
    zone: str
    area: float = 0.0

    def say(self, rng: random.Random) -> str:
        text = rng.choice(self.forms)
        # Identifiers ("gate a1") take no article; everything else is "the ...".
        return text if re.search(r"\b[a-z]+\d+\b", text) else "the " + text


def _spoken(name: str) -> str:
    return name.replace("_", " ")


def _key(form: str) -> str:
    """What a reader cannot tell apart: case, apostrophes, hyphens and plurals ("nurses' desk" =
    "nurse desk"), so a form that matches another place once lemmatised is left out."""
    words = re.sub(r"[^a-z0-9 ]", " ", form.lower().replace("'", "")).split()
    return " ".join(w[:-1] if len(w) > 3 and w.endswith("s") and not w.endswith("ss") else w for w in words)


def world_places(world: World) -> dict[str, Place]:
    """Every zone, door and entity with the forms that name it unambiguously in this world."""
    rois = world.roi_index()
    said: dict[str, set[str]] = {}
    for roi in rois:
        for form in (_spoken(roi.name), *map(_spoken, roi.aliases)):
            said.setdefault(_key(form), set()).add(roi.name)
    places = {}
    for roi in rois:
        forms = []
        for form in (_spoken(roi.name), *map(_spoken, roi.aliases)):
            form = form.lower()
            # A bare number in a place name ("desk 3", "meeting room 1") reads as a head count in a
            # sentence; such places are left out rather than given an ambiguous expected count.
            if len(said[_key(form)]) != 1 or re.search(r"(^|\s)\d+($|\s)", form) or form in forms:
                continue
            forms.append(form)
        if not forms:
            continue
        area = world.zone(roi.name).polygon.area if roi.kind == "zone" else 0.0
        places[roi.name] = Place(roi.name, tuple(forms), roi.kind, roi.zone, area)
    return places


@dataclass
class Pools:
    zones: list[Place]
    rooms: list[Place]  # zones big enough for a group to stay in (>= 20 m2)
    passages: list[Place]  # corridors, halls and lobbies: what people go "through"
    exits: list[Place]
    service: list[Place]  # where a queue forms
    seats: list[Place]
    things: list[Place]  # any entity
    people: list[tuple[str, str]]
    max_count: int


def pools_for(world: World) -> Pools:
    places = world_places(world)
    zones = [p for p in places.values() if p.kind == "zone"]
    entities = [p for p in places.values() if p.kind == "entity"]
    by_name = {e.name: e for e in world.entities()}
    service = [p for p in entities if {"queue", "service"} & set(by_name[p.name].tags)]
    if not service:  # a home has no counters: people queue for the bathroom sink or the fridge
        service = [p for p in entities if {"food", "restroom"} & set(by_name[p.name].tags)]
    seats = [p for p in entities if {"seating", "waiting"} & set(by_name[p.name].tags)]
    exits = [places[d.name] for d in world.exits() if d.name in places]
    zone_by_name = {z.name: z for z in world.zones}
    passages = [z for z in zones if "circulation" in zone_by_name[z.name].tags
                or re.search(r"corridor|hall|lobby|concourse|reception", zone_by_name[z.name].type)]
    return Pools(zones=zones, rooms=[z for z in zones if z.area >= 20], passages=passages or zones, exits=exits, service=service,
                 seats=seats, things=entities, people=PEOPLE[world.name] + GENERIC_PEOPLE,
                 max_count=MAX_COUNT[world.name])


# --------------------------------------------------------------------------------------------- clauses


@dataclass
class Clause:
    text: str  # starts lower-case; the sentence assembler capitalises
    groups: list[dict]
    preset: str = "normal"
    unknown: list[str] = field(default_factory=list)


@dataclass
class Subject:
    text: str
    singular: bool
    count: dict
    together: bool | None = None


class Slots:
    """Draws slot values for one world from one seeded generator."""

    def __init__(self, world: World, rng: random.Random):
        self.world = world
        self.rng = rng
        self.p = pools_for(world)

    def pick(self, pool: list[Place], *avoid: Place) -> Place:
        names = {a.name for a in avoid}
        return self.rng.choice([p for p in pool if p.name not in names])

    def who(self) -> tuple[str, str]:
        return self.rng.choice(self.p.people)

    def exact(self, low: int = 2, high: int | None = None) -> Subject:
        high = min(high or self.p.max_count, self.p.max_count)
        n = self.rng.randint(min(low, high), high)
        plural, singular = self.who()
        if n == 1:
            if self.rng.random() < 0.5:
                return Subject(f"{article(singular)} {singular}", True, {"kind": ["exact", "implied"], "value": 1})
            return Subject(f"one {singular}", True, {"kind": "exact", "value": 1})
        return Subject(f"{number_text(n, self.rng)} {plural}", False, {"kind": "exact", "value": n})

    def vague(self) -> Subject:
        word, low, high = self.rng.choice(VAGUE)
        plural, _ = self.who()
        return Subject(f"{word} {plural}", False, {"kind": "vague", "range": [low, high]})

    def approximate(self) -> Subject:
        n = self.rng.randint(max(5, self.p.max_count // 3), self.p.max_count)
        phrase = self.rng.choice(APPROXIMATE).format(n=number_text(n, self.rng))
        plural, _ = self.who()
        return Subject(f"{phrase} {plural}", False,
                       {"kind": "approximate", "range": [math.floor(n * 0.8), math.ceil(n * 1.2)]})

    def structured(self) -> Subject:
        parties = self.rng.randint(2, 4 if self.p.max_count >= 15 else 2)
        size = self.rng.randint(2, min(5, self.p.max_count // parties + 1))
        unit = self.rng.choice(["families", "groups", "teams", "parties"])
        text = f"{number_text(parties, self.rng)} {unit} of {number_text(size, self.rng)}"
        return Subject(text, False, {"kind": "structured", "value": parties * size, "parties": parties,
                                     "party_size": size}, together=True)

    def implied(self) -> Subject:
        if self.rng.random() < 0.5:
            return Subject("a couple", True, {"kind": "implied", "value": 2}, together=True)
        return Subject("a family", True, {"kind": "implied", "range": [2, 6]}, together=True)

    def any_subject(self) -> Subject:
        roll = self.rng.random()
        if roll < 0.55:
            return self.exact()
        if roll < 0.75:
            return self.vague()
        if roll < 0.9:
            return self.approximate()
        return self.implied()

    def duration(self) -> tuple[str, int]:
        return self.rng.choice(DURATIONS)


def group(subject: Subject, intent: str, **fields) -> dict:
    expected = {"count": dict(subject.count), "intent": intent, "robot_reaction": None}
    if subject.together is not None:
        expected["together"] = subject.together
    expected.setdefault("pace", "normal")
    expected.update(fields)
    return expected


# Each clause maker takes the slots and returns a Clause whose text says exactly its expected groups.

def walk_clause(s: Slots, subject: Subject | None = None) -> Clause:
    subject = subject or s.any_subject()
    a = s.pick(s.p.zones)
    b = s.pick(s.p.zones + s.p.things, a)
    A, B = a.say(s.rng), b.say(s.rng)
    verb = s.rng.choice(["walk", "go", "head", "make their way", "move"])
    forms = [
        (f"{subject.text} {conjugate(verb, subject.singular)} from {A} to {B}", {"start": a.name}),
        (f"{subject.text} {conjugate('leave', subject.singular)} {A} and {conjugate(verb, subject.singular)} to {B}",
         {"start": a.name}),
        (f"from {A}, {subject.text} {conjugate(verb, subject.singular)} to {B}", {"start": a.name}),
        (f"{subject.text} {conjugate(verb, subject.singular)} to {B} from {A}", {"start": a.name}),
        (f"{subject.text} {conjugate('head', subject.singular)} over to {B}", {}),
    ]
    if b.kind == "zone":
        forms.append((f"{subject.text} {conjugate('walk', subject.singular)} into {B}", {}))
    text, places = s.rng.choice(forms)
    if subject.together is None and subject.count.get("kind") == "exact":
        places["together"] = False  # numbered people walk as individuals unless the sentence groups them
    return Clause(text, [group(subject, "walk", destination=b.name, **places)])


def via_clause(s: Slots) -> Clause:
    subject = s.exact()
    c = s.pick(s.p.passages)
    b = s.pick(s.p.zones, c)
    word = s.rng.choice(["through", "via", "past"])
    verb = conjugate(s.rng.choice(["walk", "go", "head"]), subject.singular)
    text = s.rng.choice([f"{subject.text} {verb} to {b.say(s.rng)} {word} {c.say(s.rng)}",
                         f"{subject.text} {verb} {word} {c.say(s.rng)} to {b.say(s.rng)}"])
    return Clause(text, [group(subject, "walk", destination=b.name, via=[c.name])])


def pace_clause(s: Slots) -> Clause:
    subject = s.exact()
    b = s.pick(s.p.zones + s.p.exits)
    pace = s.rng.choice(["fast", "slow"])
    if pace == "fast":
        predicate = s.rng.choice(["hurry to", "rush to", "run to", "dash to", "walk quickly to", "walk briskly to",
                                  "race to"])
    else:
        predicate = s.rng.choice(["walk slowly to", "amble to", "stroll slowly to", "slowly make their way to",
                                  "shuffle slowly to", "walk leisurely to"])
    return Clause(f"{subject.text} {conjugate(predicate, subject.singular)} {b.say(s.rng)}",
                  [group(subject, "walk", destination=b.name, pace=pace)])


def together_clause(s: Slots) -> Clause:
    b = s.pick(s.p.zones + s.p.exits)
    B = b.say(s.rng)
    roll = s.rng.random()
    if roll < 0.35:
        subject = s.exact(low=2)
        verb = conjugate(s.rng.choice(["walk", "go", "head"]), subject.singular)
        text = s.rng.choice([f"{subject.text} {verb} together to {B}", f"{subject.text} {verb} to {B} as a group",
                             f"{subject.text} {verb} to {B} together"])
        subject.together = True
    elif roll < 0.55:
        n = s.rng.randint(2, s.p.max_count)
        plural, _ = s.who()
        subject = Subject(f"a group of {number_text(n, s.rng)} {plural}", True,
                          {"kind": ["exact", "structured"], "value": n}, together=True)
        text = f"{subject.text} {conjugate(s.rng.choice(['walk', 'head', 'go']), True)} to {B}"
    elif roll < 0.75:
        n = s.rng.randint(3, 5)
        subject = Subject(f"a family of {number_text(n, s.rng)}", True,
                          {"kind": ["exact", "structured", "implied"], "value": n}, together=True)
        text = f"{subject.text} {conjugate(s.rng.choice(['walk', 'head', 'go']), True)} to {B}"
    else:
        subject = s.implied()
        text = f"{subject.text} {conjugate(s.rng.choice(['walk', 'head', 'go']), True)} to {B}"
    return Clause(text, [group(subject, "walk", destination=b.name)])


def structured_clause(s: Slots) -> Clause:
    subject = s.structured()
    b = s.pick(s.p.zones + s.p.exits)
    verb = s.rng.choice(["walk together to", "head to", "go to", "make their way to"])
    return Clause(f"{subject.text} {verb} {b.say(s.rng)}", [group(subject, "walk", destination=b.name)])


def queue_clause(s: Slots, purpose: bool = False) -> Clause:
    subject = s.exact(low=2, high=10) if s.rng.random() < 0.8 else s.vague()
    q = s.pick(s.p.service)
    Q = q.say(s.rng)
    predicate = s.rng.choice(["queue at", "line up at", "stand in line at", "wait in line at", "form a queue at",
                              "queue up in front of", "get in line at"])
    text = f"{subject.text} {conjugate(predicate, subject.singular)} {Q}"
    extra: dict = {}
    if purpose:
        phrase, key = s.rng.choice(PURPOSES)
        text += f" {phrase}"
        extra["purpose"] = key
    elif s.rng.random() < 0.3:
        text = f"at {Q}, {subject.text} {conjugate('wait', subject.singular)} in line"
    if subject.count.get("kind") == "exact":
        extra["together"] = False
    return Clause(text, [group(subject, "queue", location=q.name, **extra)], preset="queuing")


def wait_clause(s: Slots, with_duration: bool = True) -> Clause:
    subject = s.exact(low=1, high=8) if s.rng.random() < 0.75 else s.vague()
    where = s.pick(s.p.rooms + s.p.seats)
    W = where.say(s.rng)
    spoken, seconds = s.duration()
    prep = "in" if where.kind == "zone" else s.rng.choice(["at", "by", "near"])
    verb = s.rng.choice(["wait", "stand", "stay", "sit"] if where.kind == "entity" else ["wait", "stay", "stand"])
    v = conjugate(verb, subject.singular)
    if not with_duration:
        text = f"{subject.text} {v} {prep} {W}"
        return Clause(text, [group(subject, "wait", location=where.name, wait_seconds=None)])
    text = s.rng.choice([f"{subject.text} {v} {prep} {W} for {spoken}", f"for {spoken}, {subject.text} {v} {prep} {W}",
                         f"{subject.text} {v} for {spoken} {prep} {W}"])
    return Clause(text, [group(subject, "wait", location=where.name, wait_seconds=float(seconds))])


def wander_clause(s: Slots, subject: Subject | None = None) -> Clause:
    subject = subject or (s.exact(low=2, high=10) if s.rng.random() < 0.6 else s.vague())
    z = s.pick(s.p.rooms)
    predicate = s.rng.choice(["wander around", "roam around", "mill around in", "walk around", "move about in",
                              "drift around"])
    return Clause(f"{subject.text} {conjugate(predicate, subject.singular)} {z.say(s.rng)}",
                  [group(subject, "wander", location=z.name)])


def converse_clause(s: Slots) -> Clause:
    subject = s.exact(low=2, high=6) if s.rng.random() < 0.7 else s.implied()
    if s.rng.random() < 0.6 or not s.p.things:
        z = s.pick(s.p.rooms)
        where, prep = z, "in"
    else:
        where, prep = s.pick(s.p.things), s.rng.choice(["near", "by", "next to"])
    predicate = s.rng.choice(["chat", "talk", "have a conversation", "chat with each other", "talk together",
                              "stand talking"])
    return Clause(f"{subject.text} {conjugate(predicate, subject.singular)} {prep} {where.say(s.rng)}",
                  [group(subject, "converse", location=where.name)])


def evacuate_clause(s: Slots) -> Clause:
    z = s.pick(s.p.rooms)
    x = s.pick(s.p.exits)
    Z, X = z.say(s.rng), x.say(s.rng)
    roll = s.rng.random()
    if roll < 0.2:
        # Everyone in the zone: the head count comes from the zone, at a sensible density.
        subject = whole_zone_subject(s, z)
        verb = s.rng.choice(["evacuate to", "are evacuated to", "evacuate towards"])
        text = f"{subject.text} {conjugate(verb, subject.singular)} {X}"
        return Clause(text, [group(subject, "evacuate", start=z.name, destination=x.name)], preset="emergency")
    subject = s.exact(low=2) if s.rng.random() < 0.7 else s.vague()
    v = lambda verb: conjugate(verb, subject.singular)  # noqa: E731
    text = s.rng.choice([
        f"evacuate {Z}: {subject.text} {v('leave')} by {X}",
        f"{Z} is being evacuated and {subject.text} {v('head')} for {X}",
        f"{subject.text} {v('evacuate')} {Z} and {v('make')} for {X}",
        f"during the evacuation of {Z}, {subject.text} {v('head')} to {X}",
        f"{subject.text} {v('evacuate')} from {Z} to {X}",
        f"{subject.text} {v('are')} evacuated from {Z} towards {X}",
    ])
    return Clause(text, [group(subject, "evacuate", start=z.name, destination=x.name)], preset="emergency")


def whole_zone_subject(s: Slots, zone: Place) -> Subject:
    # Between one person per 50 m2 and one per square metre: any sensible density passes.
    low, high = max(1, math.floor(zone.area / 50)), max(2, math.ceil(zone.area))
    plural, singular = s.who()
    text = s.rng.choice([f"everyone in {zone.say(s.rng)}", f"everybody in {zone.say(s.rng)}",
                         f"every {singular} in {zone.say(s.rng)}", f"all the {plural} in {zone.say(s.rng)}"])
    singular_verb = not text.startswith("all")
    return Subject(text, singular_verb, {"kind": "whole_zone", "range": [low, high]})


def whole_zone_clause(s: Slots) -> Clause:
    z = s.pick(s.p.rooms)
    b = s.pick(s.p.zones + s.p.exits, z)
    subject = whole_zone_subject(s, z)
    verb = conjugate(s.rng.choice(["walk", "go", "head", "move"]), subject.singular)
    return Clause(f"{subject.text} {verb} to {b.say(s.rng)}",
                  [group(subject, "walk", start=z.name, destination=b.name)])


def exclusive_clause(s: Slots) -> Clause:
    n = s.rng.randint(1, 3)
    plural, singular = s.who()
    amount = article(singular) if n == 1 and s.rng.random() < 0.5 else number_text(n, s.rng)
    who = f"{amount} {singular if n == 1 else plural}"
    subject = Subject(who, n == 1, {"kind": "exclusive", "value": n})
    z = s.pick(s.p.rooms)
    Z = z.say(s.rng)
    v = lambda verb: conjugate(verb, subject.singular)  # noqa: E731
    roll = s.rng.random()
    if roll < 0.35:
        text = s.rng.choice([f"nobody is in {Z} except {who}, who {v('wait')} there",
                             f"no one but {who} {v('wait')} in {Z}",
                             f"there is no one in {Z} apart from {who}, who {v('wait')} there"])
        return Clause(text, [group(subject, "wait", location=z.name)])
    if roll < 0.7:
        text = s.rng.choice([f"the only people in {Z} are {who}, wandering around" if n > 1 else
                             f"the only person in {Z} is {who}, wandering around",
                             f"apart from {who}, nobody is in {Z}; {'they' if n > 1 else 'the ' + singular} "
                             f"{v('wander')} around",
                             f"nobody but {who} {v('wander')} around {Z}"])
        if text.startswith("the only"):
            # "the only people are two guards" states the number outright: exact reads it right too
            subject = Subject(who, n == 1, {"kind": ["exclusive", "exact"], "value": n})
        return Clause(text, [group(subject, "wander", location=z.name)])
    b = s.pick(s.p.zones + s.p.exits, z)
    text = s.rng.choice([f"nobody moves except {who}, who {v('walk')} from {Z} to {b.say(s.rng)}",
                         f"no one except {who} {v('leave')} {Z} for {b.say(s.rng)}"])
    return Clause(text, [group(subject, "walk", start=z.name, destination=b.name)])


def negation_clause(s: Slots) -> Clause:
    subject = s.exact()
    b = s.pick(s.p.zones)
    c = s.pick(s.p.zones, b)
    B, C = b.say(s.rng), c.say(s.rng)
    v = lambda verb: conjugate(verb, subject.singular)  # noqa: E731
    text = s.rng.choice([f"{subject.text} {v('walk')} to {B}, not to {C}",
                         f"{subject.text} {v('go')} to {B} instead of {C}",
                         f"rather than {C}, {subject.text} {v('head')} to {B}",
                         f"{subject.text} {v('skip')} {C} and {v('go')} straight to {B}"])
    return Clause(text, [group(subject, "walk", destination=b.name, via=[])])


def robot_clause(s: Slots, interaction: str | None = None, subject: Subject | None = None) -> Clause:
    interaction = interaction or s.rng.choice(sorted(ROBOT))
    reaction, phrasings = ROBOT[interaction]
    subject = subject or (s.exact(low=1, high=6) if s.rng.random() < 0.8 else s.vague())
    predicate = conjugate(s.rng.choice(phrasings), subject.singular)
    text = subject.text + " " + predicate
    if s.rng.random() < 0.3:
        text = f"in {s.pick(s.p.rooms).say(s.rng)}, {text}"
    return Clause(text, [group(subject, "robot", robot_interaction=interaction, robot_reaction=reaction)])


def subset_robot_clause(s: Slots) -> Clause:
    """'N people walk to B, and one of them stares at the robot': the second group is drawn from the first."""
    first = walk_clause(s, s.exact(low=3))
    interaction = s.rng.choice(sorted(ROBOT))
    reaction, phrasings = ROBOT[interaction]
    joiner = s.rng.choice([", and one of them", "; one of them", " while one of them"])
    text = first.text + joiner + " " + conjugate(s.rng.choice(phrasings), True)
    second = {"count": {"kind": ["exact", "implied"], "value": 1}, "intent": "robot", "relation": "subset_of:0",
              "robot_interaction": interaction, "robot_reaction": reaction, "pace": "normal"}
    return Clause(text, first.groups + [second])


def more_clause(s: Slots) -> Clause:
    """'... and a few more wait in Z': a second group that adds to the first."""
    first = queue_clause(s) if s.rng.random() < 0.5 else wander_clause(s, s.exact(low=2, high=8))
    z = s.pick(s.p.rooms)
    word, low, high = s.rng.choice([("a few more", 2, 5), ("several more", 3, 8), ("some more", 2, 8)])
    verb = s.rng.choice(["wait in", "stay in", "stand in"])
    text = f"{first.text}, and {word} {verb} {z.say(s.rng)}"
    second = {"count": {"kind": "vague", "range": [low, high]}, "intent": "wait", "relation": "more_of:0",
              "location": z.name, "robot_reaction": None, "pace": "normal"}
    return Clause(text, first.groups + [second], preset=first.preset)


def others_clause(s: Slots) -> Clause:
    """'a few others wander around Z': an unnumbered second group must not be dropped."""
    first = queue_clause(s) if s.rng.random() < 0.5 else walk_clause(s, s.exact(low=2))
    plural = s.rng.choice(["a few others", "some others", "several others"])
    low, high = {"a few others": (2, 5), "some others": (2, 8), "several others": (3, 8)}[plural]
    z = s.pick(s.p.rooms)
    predicate = s.rng.choice(["wander around", "walk around", "mill around in"])
    text = f"{first.text}, while {plural} {predicate} {z.say(s.rng)}"
    second = {"count": {"kind": "vague", "range": [low, high]}, "intent": "wander", "location": z.name,
              "robot_reaction": None, "pace": "normal"}
    return Clause(text, first.groups + [second], preset=first.preset)


def follow_clause(s: Slots) -> Clause:
    first = walk_clause(s, s.exact(low=2, high=6))
    who = s.rng.choice(["a child", "a dog walker", "an assistant", "a friend", "a porter"])
    verb = s.rng.choice(["follows them", "follows behind them", "follows close behind"])
    text = f"{first.text}, and {who} {verb}"
    second = {"count": {"kind": ["exact", "implied"], "value": 1}, "intent": "follow", "robot_reaction": None,
              "pace": "normal"}
    return Clause(text, first.groups + [second])


def unknown_clause(s: Slots) -> Clause:
    """A place the world does not have: the right answer is a refusal that names it."""
    words = {w for p in world_places(s.world).values() for form in p.forms for w in form.split()}
    fake = s.rng.choice([f for f in FAKE_PLACES if not set(f.split()) & words])
    subject = s.exact()
    verb = conjugate(s.rng.choice(["walk", "go", "head"]), subject.singular)
    text = s.rng.choice([f"{subject.text} {verb} to the {fake}", f"{subject.text} {verb} from the {fake} to "
                         f"{s.pick(s.p.zones).say(s.rng)}"])
    return Clause(text, [group(subject, "walk")], unknown=[fake])


SINGLE = {  # class -> (clause maker, cases per world)
    "walk": (walk_clause, 8),
    "via": (via_clause, 4),
    "pace": (pace_clause, 8),
    "together": (together_clause, 6),
    "structured": (structured_clause, 5),
    "vague_count": (lambda s: walk_clause(s, s.vague()), 5),
    "approximate_count": (lambda s: walk_clause(s, s.approximate()), 3),
    "queue": (queue_clause, 5),
    "purpose": (lambda s: queue_clause(s, purpose=True), 6),
    "wait_duration": (wait_clause, 7),
    "wait": (lambda s: wait_clause(s, with_duration=False), 2),
    "wander": (wander_clause, 3),
    "converse": (converse_clause, 3),
    "evacuate": (evacuate_clause, 7),
    "whole_zone": (whole_zone_clause, 4),
    "exclusive": (exclusive_clause, 5),
    "negation": (negation_clause, 4),
    "robot_look": (lambda s: robot_clause(s, "look"), 3),
    "robot_approach": (lambda s: robot_clause(s, "approach"), 3),
    "robot_follow": (lambda s: robot_clause(s, "follow"), 3),
    "robot_avoid": (lambda s: robot_clause(s, "avoid"), 3),
    "robot_block": (lambda s: robot_clause(s, "block"), 3),
    "subset": (subset_robot_clause, 3),
    "more": (more_clause, 2),
    "others": (others_clause, 3),
    "follow": (follow_clause, 2),
    "unknown_place": (unknown_clause, 3),
}
# Clause makers a compound sentence draws from (each says one group).
# Evacuations are left out: the emergency preset sends everyone out, so they pair only with each
# other (class "evacuate_compound").
COMPOUND_PARTS = [walk_clause, pace_clause, queue_clause, wait_clause, wander_clause, converse_clause,
                  robot_clause, structured_clause, together_clause]
JOIN_TWO = [", while {b}", "; meanwhile, {b}", ", and {b}", ". {B}", " as {b}", ", whereas {b}"]
JOIN_THREE = ["{a}, {b}, and {c}", "{a}; {b}; {c}", "{a}, while {b} and {c}", "{a}. {B}, and {c}"]
PRESET_ORDER = ("emergency", "queuing", "normal")


def sentence(text: str) -> str:
    text = re.sub(r"(\. )([a-z])", lambda m: m.group(1) + m.group(2).upper(), text)
    return text[0].upper() + text[1:] + "."


def compound(s: Slots, parts: int, makers: list | None = None) -> Clause:
    clauses = []
    makers = makers or s.rng.sample(COMPOUND_PARTS, parts)
    for maker in makers:
        clauses.append(maker(s))
    if parts == 2:
        joiner = s.rng.choice(JOIN_TWO)
        b = clauses[1].text
        text = clauses[0].text + joiner.format(b=b, B=b[0].upper() + b[1:])
    else:
        pattern = s.rng.choice(JOIN_THREE)
        b = clauses[1].text
        text = pattern.format(a=clauses[0].text, b=b, B=b[0].upper() + b[1:], c=clauses[2].text)
    presets = {c.preset for c in clauses}
    preset = next(p for p in PRESET_ORDER if p in presets)
    return Clause(text, [g for c in clauses for g in c.groups], preset=preset)


def build_cases() -> list[dict]:
    cases = []
    for world_name in WORLDS:
        world = load_world(world_name)
        classes = dict(SINGLE)
        classes["compound_2"] = (lambda s: compound(s, 2), 10)
        classes["compound_3"] = (lambda s: compound(s, 3), 5)
        classes["evacuate_compound"] = (lambda s: compound(s, 2, [evacuate_clause, evacuate_clause]), 3)
        for cls, (maker, per_world) in classes.items():
            slots = Slots(world, random.Random(f"{world_name}/{cls}"))
            seen: set[str] = set()
            index = 0
            attempts = 0
            while index < per_world:
                attempts += 1
                if attempts > per_world * 50:
                    raise RuntimeError(f"{world_name}/{cls}: cannot draw {per_world} distinct prompts")
                clause = maker(slots)
                check_places(world, clause)
                prompt = sentence(clause.text)
                if prompt in seen or not fits(world, clause):
                    continue
                seen.add(prompt)
                index += 1
                cases.append({
                    "id": f"{world_name}-{cls}-{index:02d}",
                    "world": world_name,
                    "preset": clause.preset,
                    "class": cls,
                    "prompt": prompt,
                    "expect": {"groups": clause.groups, "unknown_places": clause.unknown},
                })
    return cases


# People a zone can take as a destination or a place to stay: one per two square metres of its area,
# so the scenario the sentence asks for can be built (a world's small rooms refuse larger groups).
PEOPLE_PER_M2 = 0.5


def _typical(count: dict) -> float:
    if "value" in count:
        return float(count["value"])
    low, high = count["range"]
    return low + (high - low) / 4  # a reader's seeded choice sits low in a wide range more often than not


def fits(world: World, clause: Clause) -> bool:
    """Whether the groups sent to (or staying in) each zone fit in it at PEOPLE_PER_M2."""
    load: dict[str, float] = {}
    for expected in clause.groups:
        target = expected.get("destination") or expected.get("location")
        if target is None:
            continue
        place = world.find(target)
        zone = target if hasattr(place, "boundary") else place.zone
        if getattr(place, "leads_to", None) == "outside":
            continue  # people leaving by an exit do not stay in its zone
        load[zone] = load.get(zone, 0.0) + _typical(expected["count"])
    return all(people <= world.zone(zone).polygon.area * PEOPLE_PER_M2 for zone, people in load.items())


def check_places(world: World, clause: Clause) -> None:
    """Every expected place is one of the world's own names (a typo here would score the reader wrong)."""
    known = {roi.name for roi in world.roi_index()}
    for expected in clause.groups:
        named = [expected.get(role) for role in ("start", "destination", "location")] + expected.get("via", [])
        unknown = [name for name in named if name is not None and name not in known]
        if unknown:
            raise RuntimeError(f"{world.name}: {clause.text!r} expects unknown places {unknown}")


HEADER = """\
# The public understanding suite: generated by eval/understanding/build.py, do not edit by hand.
# Each case: a prompt in a shipped world and the reading it must produce. Per expected group:
#   count: kind (a string, or a list when English allows either), and value (exact) or range [low, high]
#          (inclusive: vague and whole-zone counts are a seeded choice, approximate ones +-20 %),
#          parties / party_size for structured counts;
#   intent, start / destination / location / via (the world's own place names), robot_interaction,
#   robot_reaction (null: none), together, pace, wait_seconds, purpose (a word the purpose contains),
#   relation. A field that is absent is not scored for that group.
# unknown_places: places the prompt names that the world does not have (a refusal is expected);
# an empty list means any unknown place in the reading is a false refusal.
"""


def render(cases: list[dict]) -> str:
    body = yaml.safe_dump({"version": 1, "cases": cases}, sort_keys=False, allow_unicode=True, width=120,
                          default_flow_style=None)
    return HEADER + body


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=HERE / "cases.yaml")
    parser.add_argument("--check", action="store_true", help="exit 1 if --out differs from what would be built")
    args = parser.parse_args(argv)
    text = render(build_cases())
    if args.check:
        same = args.out.exists() and args.out.read_text(encoding="utf-8") == text
        print("up to date" if same else f"{args.out} is stale: run python eval/understanding/build.py")
        return 0 if same else 1
    args.out.write_text(text, encoding="utf-8")
    print(f"{args.out}: {text.count(chr(10) + '- id: ')} cases")
    return 0


if __name__ == "__main__":
    sys.exit(main())
