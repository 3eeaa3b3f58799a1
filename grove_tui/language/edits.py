"""The typed reading of a follow-up sentence: what it asks to change in a scenario that exists.

A follow-up ("add a cleaner mopping the corridor", "make the queue twice as long", "the visitors walk
to the cafeteria instead", "remove the cleaner", "no robot", "the robot waits at reception") is read
by `language.followup.read_followup` against the scenario's groups into an `EditReading`: one
`GroupEdit` per group it adds, changes or removes, and at most one `RobotEdit`. Everything below
(`generation/refine.py`) takes this reading; nothing there reads English.

A group of the scenario is named by its index in the list of `GroupReading`s the follow-up was read
against. A phrase that could mean several groups ("the nurse" with two nurse groups) is a `GroupRef`
with several candidates and `ambiguous` set: the app asks which, the CLI exits 2 with the choices,
and `EditReading.choose` records the answer.

Plain data: `to_dict()` / `from_dict()` round-trip it through the bundle's history.
`edited_reading(old, edit)` is what a change does to a group's reading.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Any

from grove_tui.jsontypes import JSONObject, Parsed

from grove_tui.language import lexicon as lx
from grove_tui.language.model import Count, GroupReading, RobotReading

EDIT_KINDS = ("add", "change", "remove")
ROBOT_EDIT_KINDS = ("add", "set", "remove")
COUNT_CHANGE_KINDS = ("set", "factor", "delta")
# Fields of a GroupReading a follow-up can restate; a change sets exactly the ones it states.
EDITABLE_FIELDS = ("count", "intent", "start", "destination", "location", "via", "pace", "together",
                   "wait_seconds", "robot_interaction")
MIN_COUNT = 1


@dataclass(frozen=True)
class CountChange:
    """A new head count: "twenty patients" (set 20), "twice as long" (factor 2), "two fewer" (delta -2)."""

    kind: str  # one of COUNT_CHANGE_KINDS
    value: float

    def apply(self, count: int) -> int:
        """The new count of a group of `count` people (never below one: a group of none is removed)."""
        if self.kind == "set":
            return max(MIN_COUNT, int(round(self.value)))
        if self.kind == "factor":
            return max(MIN_COUNT, int(round(count * self.value)))
        return max(MIN_COUNT, count + int(round(self.value)))

    def removes(self, count: int) -> bool:
        """A delta that takes away everyone ("remove the three nurses" of three) removes the group."""
        return self.kind == "delta" and count + int(round(self.value)) < MIN_COUNT

    def describe(self) -> str:
        if self.kind == "set":
            return f"{int(self.value)} people"
        if self.kind == "factor":
            return f"x{self.value:g}"
        return f"{int(self.value):+d}"

    def to_dict(self) -> JSONObject:
        return {"kind": self.kind, "value": self.value}

    @classmethod
    def from_dict(cls, data: Parsed) -> CountChange:
        return cls(str(data["kind"]), float(data["value"]))


@dataclass(frozen=True)
class GroupRef:
    """How a follow-up names groups of the scenario ("the nurse", "the queue", "the people at the
    pharmacy", "everyone") and which groups that can be (indices into the groups it was read against)."""

    phrase: str
    candidates: tuple[int, ...]
    every: bool = False  # "everyone", "all the nurses", "both": every candidate is meant

    @property
    def ambiguous(self) -> bool:
        return len(self.candidates) > 1 and not self.every

    @property
    def found(self) -> bool:
        return bool(self.candidates)

    @property
    def targets(self) -> tuple[int, ...]:
        """The groups meant; empty while the phrase is ambiguous or names no group."""
        return () if self.ambiguous else self.candidates

    def to_dict(self) -> JSONObject:
        return {"phrase": self.phrase, "candidates": list(self.candidates), "every": self.every}

    @classmethod
    def from_dict(cls, data: Parsed) -> GroupRef:
        return cls(str(data["phrase"]), tuple(int(c) for c in data.get("candidates", ())), bool(data.get("every")))


@dataclass(frozen=True)
class GroupEdit:
    """One group added, changed or removed.

    add: `group` is the new group's reading; `target`, when set, is the group it copies what it does
    from ("two more nurses": the nurses). change: `target` is the group changed, `group` the follow-up's
    own reading of it, of which only `fields` are taken, and `count` its new head count. remove:
    `target` alone."""

    kind: str  # one of EDIT_KINDS
    text: str  # the words of the follow-up this edit comes from
    target: GroupRef | None = None
    group: GroupReading | None = None
    fields: tuple[str, ...] = ()  # the fields a change states (EDITABLE_FIELDS)
    count: CountChange | None = None

    def to_dict(self) -> JSONObject:
        return {"kind": self.kind, "text": self.text,
                "target": self.target.to_dict() if self.target is not None else None,
                "group": self.group.to_dict() if self.group is not None else None,
                "fields": list(self.fields), "count": self.count.to_dict() if self.count is not None else None}

    @classmethod
    def from_dict(cls, data: Parsed) -> GroupEdit:
        return cls(str(data["kind"]), str(data.get("text", "")),
                   GroupRef.from_dict(data["target"]) if data.get("target") else None,
                   GroupReading.from_dict(data["group"]) if data.get("group") else None,
                   tuple(str(f) for f in data.get("fields", ())),
                   CountChange.from_dict(data["count"]) if data.get("count") else None)


@dataclass(frozen=True)
class RobotEdit:
    """The robot: removed ("no robot"), added back ("add a robot"), or given a task ("the robot waits at
    reception": `robot` is what the follow-up asks of it)."""

    kind: str  # one of ROBOT_EDIT_KINDS
    text: str
    robot: RobotReading | None = None

    def to_dict(self) -> JSONObject:
        return {"kind": self.kind, "text": self.text, "robot": self.robot.to_dict() if self.robot else None}

    @classmethod
    def from_dict(cls, data: Parsed) -> RobotEdit:
        return cls(str(data["kind"]), str(data.get("text", "")),
                   RobotReading.from_dict(data["robot"]) if data.get("robot") else None)


@dataclass(frozen=True)
class EditReading:
    sentence: str
    edits: tuple[GroupEdit, ...] = ()
    robot: RobotEdit | None = None
    notes: tuple[str, ...] = ()  # what could not be read, said plainly ("'the janitor' names no group")

    @property
    def empty(self) -> bool:
        return not self.edits and self.robot is None

    def ambiguities(self) -> list[tuple[int, GroupRef]]:
        """(edit index, its reference) for every edit whose group is not settled yet."""
        return [(i, e.target) for i, e in enumerate(self.edits) if e.target is not None and e.target.ambiguous]

    def choose(self, edit: int, group: int) -> EditReading:
        """The reading with edit `edit`'s ambiguous reference settled on group `group` (a candidate)."""
        target = self.edits[edit].target
        if target is None or group not in target.candidates:
            raise ValueError(f"group {group} is not a candidate of edit {edit}")
        edits = list(self.edits)
        edits[edit] = replace(edits[edit], target=replace(target, candidates=(group,), every=False))
        return replace(self, edits=tuple(edits))

    def to_dict(self) -> JSONObject:
        return {"sentence": self.sentence, "edits": [e.to_dict() for e in self.edits],
                "robot": self.robot.to_dict() if self.robot is not None else None, "notes": list(self.notes)}

    @classmethod
    def from_dict(cls, data: Parsed) -> EditReading:
        return cls(str(data.get("sentence", "")), tuple(GroupEdit.from_dict(e) for e in data.get("edits", ())),
                   RobotEdit.from_dict(data["robot"]) if data.get("robot") else None,
                   tuple(str(n) for n in data.get("notes", ())))


def edited_reading(old: GroupReading, edit: GroupEdit) -> GroupReading:
    """A group's reading after a change: the fields the follow-up states replace the old ones, and
    places that belonged to what the group no longer does go with it ("the visitors walk to the
    cafeteria instead": no longer queueing at the pharmacy)."""
    new = edit.group
    values: dict[str, Any] = {}  # Any: field values of several types, handed to dataclasses.replace
    fields = set(edit.fields)
    if edit.count is not None:
        value = edit.count.apply(old.count.value)
        values["count"] = Count("exact", value, value, value)
    if new is not None:
        if "intent" in fields and new.intent == "walk" and old.intent == "evacuate":
            fields.discard("intent")  # "the patients leave through the east exit": they still evacuate, there
        if "intent" in fields and new.intent != old.intent:
            values["intent"] = new.intent
            stationary = new.intent in lx.STATIONARY_INTENTS
            if stationary and "location" not in fields:
                # what they now do, they do where they were (waiting instead of queueing at the desk)
                values["location"] = old.location or (old.destination if old.intent not in lx.STATIONARY_INTENTS
                                                      else None)
            if stationary and "destination" not in fields:
                values["destination"] = None
            if not stationary and new.intent != "robot" and "location" not in fields:
                values["location"] = None
            if not stationary and new.intent != "robot" and "destination" not in fields and \
                    old.intent in lx.STATIONARY_INTENTS:
                values["destination"] = None
        for name in ("start", "destination", "location", "via", "pace", "together", "wait_seconds"):
            if name in fields:
                values[name] = getattr(new, name)
        if "robot_interaction" in fields:
            values["robot_interaction"] = new.robot_interaction
            values["robot_reaction"] = new.robot_reaction
            if new.robot_interaction is None and old.intent == "robot":
                values["intent"] = "walk" if (values.get("destination", old.destination)) else "wait"
        if "destination" in fields and "location" not in fields and old.intent in lx.STATIONARY_INTENTS and \
                values.get("intent", old.intent) not in lx.STATIONARY_INTENTS:
            values["location"] = None
    text = f"{old.text} / {edit.text}" if old.text else edit.text
    return replace(old, **values, text=text, relation=None, confidence=())
