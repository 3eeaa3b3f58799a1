"""The typed reading of a sentence: the contract between `language/` and everything downstream.

The sentence is read once (`language.reading.read_prompt`) into a `PromptReading`: its groups of
people (`GroupReading`), what the sentence asks of the robot (`RobotReading`), and how sure the
reader is of each field (`FieldConfidence`). Every stage below takes this reading; the raw text goes
only to the language model and the embedder.

Plain data: `to_dict()` / `from_dict()` round-trip it through generation.json.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import asdict, dataclass

from grove_tui.jsontypes import JSONObject, Parsed

COUNT_KINDS = ("exact", "approximate", "vague", "implied", "structured", "whole_zone", "exclusive")
INTENTS = ("walk", "queue", "wait", "wander", "converse", "follow", "evacuate", "robot")
ROBOT_INTERACTIONS = ("look", "approach", "follow", "avoid", "block")
# What a group reacting to the robot does besides reacting ("queue at the pharmacy and look at the robot").
ROUTINES = ("walk", "queue", "wait", "wander", "converse")
# What a sentence can ask the robot itself to do ("the robot crosses the hall to the lifts": cross).
ROBOT_TASKS = ("cross", "wait", "patrol", "follow")
# A field the reader is less sure of than this is "unsure": the report says so, the app asks first,
# and `grove generate --strict` refuses it.
UNSURE_BELOW = 0.6


@dataclass(frozen=True)
class FieldConfidence:
    """How sure the reader is of one field of a group (or of the robot) and why.

    `score` is 1.0 for a field read from words that say it outright ("ten", "the pharmacy"), lower
    when it was inferred (an implied group, a guessed count, a place matched by meaning, two places
    scoring alike). `alternatives` are the other values the reader weighed, best first, so a
    question can offer them ("the big meeting room: the boardroom, or the meeting room?").
    """

    field: str  # "count", "start", "destination", "location", "intent", "robot_interaction", "group"
    score: float
    reason: str = ""
    alternatives: tuple[str, ...] = ()

    @property
    def unsure(self) -> bool:
        return self.score < UNSURE_BELOW

    def to_dict(self) -> JSONObject:
        return {"field": self.field, "score": self.score, "reason": self.reason,
                "alternatives": list(self.alternatives)}

    @classmethod
    def from_dict(cls, data: Parsed) -> FieldConfidence:
        return cls(str(data["field"]), float(data["score"]), str(data.get("reason", "")),
                   tuple(str(a) for a in data.get("alternatives", ())))


def _confidences(data: Sequence[Parsed] | None) -> tuple[FieldConfidence, ...]:
    return tuple(FieldConfidence.from_dict(c) for c in (data or ()))


@dataclass(frozen=True)
class Count:
    kind: str  # one of COUNT_KINDS
    value: int  # the head count the scenario will use (seeded choice inside [low, high] when not exact)
    low: int
    high: int
    parties: int | None = None  # "three families of four": parties=3, party_size=4, value=12
    party_size: int | None = None

    def to_dict(self) -> JSONObject:
        return asdict(self)

    @classmethod
    def from_dict(cls, data: Parsed) -> Count:
        return cls(str(data["kind"]), int(data["value"]), int(data["low"]), int(data["high"]),
                   data.get("parties"), data.get("party_size"))


@dataclass(frozen=True)
class GroupReading:
    who: str  # the noun phrase as written ("patients", "a family", "a few others")
    label: str  # short label, never a number word nor a node name ("patient", "family")
    count: Count
    intent: str  # one of INTENTS
    robot_interaction: str | None = None  # one of ROBOT_INTERACTIONS
    robot_reaction: str | None = None  # HuNavSim behavior type for the interaction
    start: str | None = None  # world place name where they start
    destination: str | None = None  # where they go
    location: str | None = None  # where they are, for stationary intents
    via: tuple[str, ...] = ()  # "through", "via", "past"
    purpose: str | None = None  # a purpose that is not a place: "to check in", "for coffee"
    wait_seconds: float | None = None  # "for five minutes" -> 300.0
    # the wait_seconds are a stay where they start before the intent ("sit ... for five minutes before queuing")
    waits_first: bool = False
    together: bool = False  # "together", "as a group", families, couples
    pace: str = "normal"  # "slow" | "normal" | "fast"
    relation: str | None = None  # "subset_of:0", "others_of:0", "more_of:0"
    follows: str | None = None  # whom a "follow" group follows, as written ("the nurse")
    text: str = ""  # the prompt words this group owns
    confidence: tuple[FieldConfidence, ...] = ()  # per field; a field not listed was read outright
    avoid: tuple[str, ...] = ()  # places the sentence says they do not use ("not the main doors")
    # For intent "robot": what they do besides reacting, one of ROUTINES, at the group's places
    # ("six patients queue at the pharmacy and look at the robot": routine "queue", location pharmacy).
    routine: str | None = None
    # Their reaction happens as the robot passes ("... look at the robot as it passes the desk"), and the
    # place it passes then (the robot's via; None: as it passes them): language/passing_moment.py.
    reacts_as_robot_passes: bool = False
    passed_place: str | None = None

    def confidence_of(self, name: str) -> FieldConfidence | None:
        return next((c for c in self.confidence if c.field == name), None)

    def related_to(self, kind: str) -> int | None:
        """The index of the group this one is `kind` of ("subset_of", "others_of", "more_of"), else None."""
        said, _, parent = (self.relation or "").partition(":")
        return int(parent) if said == kind and parent.isdigit() else None

    def to_dict(self) -> JSONObject:
        data = asdict(self)
        data["count"] = self.count.to_dict()
        data["via"] = list(self.via)
        data["avoid"] = list(self.avoid)
        data["confidence"] = [c.to_dict() for c in self.confidence]
        return data

    @classmethod
    def from_dict(cls, data: Parsed) -> GroupReading:
        values = dict(data)
        values["count"] = Count.from_dict(values["count"])
        values["via"] = tuple(values.get("via", ()))
        values["avoid"] = tuple(values.get("avoid", ()))
        values["confidence"] = _confidences(values.get("confidence"))
        known = {f for f in cls.__dataclass_fields__}
        return cls(**{k: v for k, v in values.items() if k in known})


@dataclass(frozen=True)
class RobotReading:
    """What the sentence asks of the robot itself: "a robot crosses the ticket hall to the
    platforms" is task "cross", via ("ticket_hall",), destination "platform_1"; "the robot waits by
    reception" is task "wait" at location "reception". Places are the world's own names; a place
    of the robot's clause is never a group's place."""

    task: str  # one of ROBOT_TASKS
    start: str | None = None
    destination: str | None = None
    location: str | None = None  # where it stays, for "wait"
    via: tuple[str, ...] = ()
    text: str = ""  # the prompt words of the robot's clause
    confidence: tuple[FieldConfidence, ...] = ()
    follows: str | None = None  # whom a "follow" task follows, as written ("a porter", "him")
    # how long a "wait" lasts when said ("waits at the cloakroom for two minutes": 120); None for no
    # length or the whole scenario, as a group's wait_seconds
    wait_seconds: float | None = None
    # whom a "cross" the robot leads takes along, as written ("them", "the passengers"): "the robot
    # guides them to the exit" goes where they go
    guides: str | None = None
    # the groups (their `who`) its clause goes through, past or around ("threads its way through the crowd
    # of visitors", "drives through the queue"): their places are among `via`, and it is to pass them
    passes: tuple[str, ...] = ()
    # places its clause says it keeps out of ("drives to the pharmacy, avoiding the cafeteria", "without going
    # through the waiting room"): never among its start, destination, location or via; its path goes round them
    avoid: tuple[str, ...] = ()

    def confidence_of(self, name: str) -> FieldConfidence | None:
        return next((c for c in self.confidence if c.field == name), None)

    def to_dict(self) -> JSONObject:
        return {"task": self.task, "start": self.start, "destination": self.destination,
                "location": self.location, "via": list(self.via), "text": self.text,
                "confidence": [c.to_dict() for c in self.confidence], "follows": self.follows,
                "wait_seconds": self.wait_seconds, "guides": self.guides, "passes": list(self.passes),
                "avoid": list(self.avoid)}

    @classmethod
    def from_dict(cls, data: Parsed) -> RobotReading:
        seconds = data.get("wait_seconds")
        return cls(str(data["task"]), data.get("start"), data.get("destination"), data.get("location"),
                   tuple(data.get("via", ())), str(data.get("text", "")), _confidences(data.get("confidence")),
                   data.get("follows"), float(seconds) if seconds is not None else None, data.get("guides"),
                   tuple(data.get("passes", ())), tuple(data.get("avoid", ())))


@dataclass(frozen=True)
class PromptReading:
    prompt: str
    groups: tuple[GroupReading, ...]
    unknown_places: tuple[str, ...] = ()  # noun phrases in a PLACE role that the world does not have
    notes: tuple[str, ...] = ()  # what could not be honoured, said plainly
    corrections: tuple[str, ...] = ()  # misspelt place words read as the world's ("read 'kitchn' as 'kitchen'")
    robot: RobotReading | None = None  # what the sentence asks of the robot itself; None when it asks nothing
    places: tuple[str, ...] = ()  # every place of the world the sentence names, in reading order
    problems: tuple[str, ...] = ()  # what the sentence asks that no scenario can be ("-5 people"), said plainly

    def to_dict(self) -> JSONObject:
        return {"prompt": self.prompt, "groups": [g.to_dict() for g in self.groups],
                "unknown_places": list(self.unknown_places), "notes": list(self.notes),
                "corrections": list(self.corrections),
                "robot": self.robot.to_dict() if self.robot is not None else None,
                "places": list(self.places), "problems": list(self.problems)}

    @classmethod
    def from_dict(cls, data: Parsed) -> PromptReading:
        return cls(str(data.get("prompt", "")), tuple(GroupReading.from_dict(g) for g in data.get("groups", ())),
                   tuple(data.get("unknown_places", ())), tuple(data.get("notes", ())),
                   tuple(data.get("corrections", ())),
                   RobotReading.from_dict(data["robot"]) if data.get("robot") else None,
                   tuple(data.get("places", ())), tuple(data.get("problems", ())))

    def unsure(self) -> list[tuple[int | None, FieldConfidence]]:
        """(group index, or None for the robot; the field) for every field read with low confidence."""
        found: list[tuple[int | None, FieldConfidence]] = [
            (i, c) for i, g in enumerate(self.groups) for c in g.confidence if c.unsure]
        if self.robot is not None:
            found += [(None, c) for c in self.robot.confidence if c.unsure]
        return found

    @property
    def total(self) -> int:
        """People in the scenario: every group, less the subsets counted inside their parent."""
        return sum(effective_counts(self).values())


def effective_counts(reading: PromptReading) -> dict[int, int]:
    """Group index -> people of its own: a parent loses the members of its subsets ("one of them")
    and of "the others" read as the rest of it; a parent left with nobody is absent."""
    counts = {i: g.count.value for i, g in enumerate(reading.groups)}
    for i, g in enumerate(reading.groups):
        subset, others = g.related_to("subset_of"), g.related_to("others_of")
        p = subset if subset is not None else \
            others if others is not None and g.count.kind == "implied" and _has_subset(reading, others) else None
        if p is not None and p in counts:
            counts[p] = max(0, counts[p] - g.count.value)
    return {i: c for i, c in counts.items() if c > 0}


def _has_subset(reading: PromptReading, parent: int) -> bool:
    return any(g.relation == f"subset_of:{parent}" for g in reading.groups)
