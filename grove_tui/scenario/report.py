"""The grounding report: for every group (and the robot), what the sentence asked, what the scenario
plans to do about it, and, after a run, whether the people did it.

A ✓ is a claim about the world: it is earned by a measured outcome in the run, never by a node's name
or by the scenario agreeing with its own reading of the sentence. So the report has two states:

- *planned* (generation.json `grounding`): every claim says what the scenario plans and the place,
  point, partners or pace a run must show; nothing is ✓ yet. A claim the plan already contradicts
  (a group the scenario lost, a count that differs) is ✗ here.
- *checked* (grounding.json beside metrics.json, written by every run): `analysis/outcomes.py` checks
  every claim against trajectories.csv and events.jsonl. ✓ only with the measured figure, ✗ with the
  figure, "not checked" when the run was too short to tell (with how long it needs).

What the scenario does beyond the reading (the model's extra Wait at the end, say) is listed as
*added*, never counted as ✓. Readings the reader was unsure of are listed as questions.

Plain data, no English is read here: generation/reconcile.py builds the planned report from the
reading and the post-processed groups.

    report = GroundingReport.from_dict(json.loads(Path("grounding.json").read_text()))
    for line in report.lines():
        print(line)
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

from grove_tui.jsontypes import JSONObject, Parsed

OK_MARK = "✓"
FAIL_MARK = "✗"
PLANNED_MARK = "·"
UNCHECKED_MARK = "?"

PLANNED, HOLDS, FAILS, UNCHECKED = "planned", "holds", "fails", "unchecked"
STATUSES = (PLANNED, HOLDS, FAILS, UNCHECKED)
MARKS = {PLANNED: PLANNED_MARK, HOLDS: OK_MARK, FAILS: FAIL_MARK, UNCHECKED: UNCHECKED_MARK}

# What a claim says about a group, each checked by analysis/outcomes.py the same way everywhere.
GROUP_CLAIMS = (
    "count",           # this many people take part (the first frame of the run)
    "start",           # they start in `zone`
    "reach",           # they get to `zone` (or within `radius` of `point`)
    "stay",            # they stay at `zone` / `point` (for `seconds` when asked)
    "wander",          # they move around inside `zone`
    "move",            # they walk (the sentence names no destination)
    "leave",           # they leave `zone` (the sentence names where from, not where to)
    "queue",           # they join the line at `place`, it advances, people are served
    "converse",        # they talk with `partners` (a conversation event)
    "evacuate",        # they leave the building (through `exits` when named)
    "follow_person",   # they keep within `distance` of `partners`
    "robot_follow",    # they keep within `distance` of the robot while it moves
    "robot_approach",  # they come within `distance` of the robot
    "robot_block",     # they stand in the robot's path and slow it
    "robot_avoid",     # they move away when the robot comes near
    "robot_look",      # they face the robot while it is in sight
    "pace",            # their walking speed is `pace` (slow/fast), between `low` and `high` m/s
    "keep_out",        # they never set foot in `zone` (or within `radius` of `point`): "avoiding the lifts"
)
ROBOT_CLAIMS = ("robot_reach", "robot_via", "robot_stay", "robot_patrol", "robot_follow_person",
                "robot_pickup",    # it stands `seconds` at the pick-up place of its errand
                "robot_dropoff",   # it gets to the drop-off place after that stop, and stands there
                "robot_beside")    # it passes the people standing at a place beside them: never within `distance`
CLAIM_KINDS = GROUP_CLAIMS + ROBOT_CLAIMS

Point = tuple[float, float]


@dataclass(frozen=True)
class Claim:
    """One thing the sentence asks of a group or of the robot, as a run can check it.

    `asked` and `plan` are for people (what the sentence says, what the scenario does about it); the
    other fields are what the check measures against: world places by name, points, agent ids.
    """

    kind: str  # one of CLAIM_KINDS
    asked: str  # as the sentence states it ("platform_1", "slow", "12", "follow the robot")
    plan: str  # what the scenario does for it ("walk to platform_1", "ApproachRobot, 1.0 m")
    status: str = PLANNED  # one of STATUSES
    evidence: str = ""  # the measured figure after a run; why it fails or cannot be checked
    needs_seconds: float | None = None  # how long a run must be before the outcome can be told
    zone: str | None = None  # a world zone the outcome happens in
    place: str | None = None  # the world place by name (zone, door or entity), for queues and labels
    point: Point | None = None  # a door's or entity's point, when the place is not a zone
    radius: float = 0.0  # within this of `point` counts as there
    exits: tuple[str, ...] = ()  # named exits, for evacuations
    partners: tuple[int, ...] = ()  # agent ids: the conversation's or the followed people
    seconds: float | None = None  # an asked duration ("waits for five minutes": 300); a reach after a wait: the wait
    distance: float | None = None  # metres, for reactions and following
    low: float | None = None  # m/s, for pace
    high: float | None = None
    share: float = 0.9  # the share of the group's members that must show the outcome
    moment: str | None = None  # "pass": a reaction checked only while the robot passes (generation/passing_look.py)

    @property
    def mark(self) -> str:
        return MARKS.get(self.status, UNCHECKED_MARK)

    def checked(self, status: str, evidence: str) -> Claim:
        return replace(self, status=status, evidence=evidence)

    def to_dict(self) -> JSONObject:
        data: JSONObject = {"kind": self.kind, "asked": self.asked, "plan": self.plan, "status": self.status,
                            "evidence": self.evidence}
        for name in ("needs_seconds", "zone", "place", "seconds", "distance", "low", "high", "moment"):
            value = getattr(self, name)
            if value is not None:
                data[name] = value
        if self.point is not None:
            data["point"] = [self.point[0], self.point[1]]
            data["radius"] = self.radius
        if self.exits:
            data["exits"] = list(self.exits)
        if self.partners:
            data["partners"] = list(self.partners)
        if self.share != 0.9:
            data["share"] = self.share
        return data

    @classmethod
    def from_dict(cls, data: Parsed) -> Claim:
        point = data.get("point")
        return cls(str(data["kind"]), str(data.get("asked", "")), str(data.get("plan", "")),
                   str(data.get("status", PLANNED)), str(data.get("evidence", "")),
                   _float(data.get("needs_seconds")), _str(data.get("zone")), _str(data.get("place")),
                   (float(point[0]), float(point[1])) if point else None, float(data.get("radius", 0.0)),
                   tuple(str(e) for e in data.get("exits", ())), tuple(int(p) for p in data.get("partners", ())),
                   _float(data.get("seconds")), _float(data.get("distance")), _float(data.get("low")),
                   _float(data.get("high")), float(data.get("share", 0.9)), _str(data.get("moment")))


def _float(value: float | str | None) -> float | None:
    return None if value is None else float(value)


def _str(value: object) -> str | None:
    return None if value is None else str(value)


def verdict(claims: tuple[Claim, ...]) -> str:
    """A group's (or the robot's) verdict: fails if any claim fails, holds only if every one holds,
    else planned (before a run) or unchecked (a run too short for some claim)."""
    statuses = {c.status for c in claims}
    if FAILS in statuses:
        return FAILS
    if not claims:
        return PLANNED
    if statuses == {HOLDS}:
        return HOLDS
    return UNCHECKED if UNCHECKED in statuses else PLANNED


@dataclass(frozen=True)
class GroupGrounding:
    who: str  # the phrase of the sentence ("two families of three")
    label: str  # the group's label in the scenario
    claims: tuple[Claim, ...]
    members: tuple[int, ...] = ()  # agent ids of the group in the scenario
    added: tuple[str, ...] = ()  # what the scenario does beyond the reading ("waits 10 s at the end")
    unsure: tuple[str, ...] = ()  # questions about fields the reader was unsure of
    edit: str = ""  # a user's count edit, said beside what the sentence asked
    asked_by: int = 0  # the sentence that asked for the group: 0 the first, k the k-th follow-up
    changed_by: tuple[int, ...] = ()  # the follow-ups that changed it

    @property
    def status(self) -> str:
        return verdict(self.claims)

    @property
    def ok(self) -> bool:
        """Checked, and every claim holds in the run."""
        return self.status == HOLDS

    def asked(self) -> str:
        """Which sentence asked for the group, and which changed it: "sentence 1, changed by 3"."""
        text = f"sentence {self.asked_by + 1}"
        if self.changed_by:
            text += ", changed by " + ", ".join(str(c + 1) for c in self.changed_by)
        return text

    def to_dict(self) -> JSONObject:
        data: JSONObject = {"who": self.who, "label": self.label, "status": self.status, "ok": self.ok,
                            "members": list(self.members), "claims": [c.to_dict() for c in self.claims]}
        if self.added:
            data["added"] = list(self.added)
        if self.unsure:
            data["unsure"] = list(self.unsure)
        if self.edit:
            data["edit"] = self.edit
        if self.asked_by:
            data["asked_by"] = self.asked_by
        if self.changed_by:
            data["changed_by"] = list(self.changed_by)
        return data

    @classmethod
    def from_dict(cls, data: Parsed) -> GroupGrounding:
        claims = tuple(Claim.from_dict(c) for c in data.get("claims", ()))
        if not claims and data.get("checks"):
            claims = tuple(_legacy_claim(c) for c in data["checks"])
        return cls(str(data.get("who", "")), str(data.get("label", "")), claims,
                   tuple(int(m) for m in data.get("members", ())), tuple(str(a) for a in data.get("added", ())),
                   tuple(str(u) for u in data.get("unsure", ())), str(data.get("edit", "")),
                   int(data.get("asked_by", 0)), tuple(int(c) for c in data.get("changed_by", ())))


def _legacy_claim(check: Parsed) -> Claim:
    """A check of a report written before outcomes were checked: it agreed with the reading at most,
    so it is only planned (or ✗ where it already disagreed)."""
    ok = bool(check.get("ok", False))
    return Claim(str(check.get("field", "check")), str(check.get("asked", "")), str(check.get("does", "")),
                 PLANNED if ok else FAILS, "" if ok else str(check.get("reason", "")))


@dataclass(frozen=True)
class RobotGrounding:
    """The robot's row: what the sentence asks the robot to do, and (after a run) whether it did."""

    task: str  # "cross", "wait", "patrol", "follow", or "pass" when the sentence asks nothing of it
    text: str  # the robot's clause, or "" when the sentence asks nothing of it
    claims: tuple[Claim, ...]
    plan: str = ""  # the route in words ("from ticket_hall (3.1, 4.0) to platform_1 (40.2, 4.5), 38 m")
    unsure: tuple[str, ...] = ()

    @property
    def status(self) -> str:
        return verdict(self.claims)

    @property
    def ok(self) -> bool:
        return self.status == HOLDS

    def to_dict(self) -> JSONObject:
        data: JSONObject = {"task": self.task, "text": self.text, "plan": self.plan, "status": self.status,
                            "ok": self.ok, "claims": [c.to_dict() for c in self.claims]}
        if self.unsure:
            data["unsure"] = list(self.unsure)
        return data

    @classmethod
    def from_dict(cls, data: Parsed) -> RobotGrounding:
        return cls(str(data.get("task", "pass")), str(data.get("text", "")),
                   tuple(Claim.from_dict(c) for c in data.get("claims", ())), str(data.get("plan", "")),
                   tuple(str(u) for u in data.get("unsure", ())))


@dataclass(frozen=True)
class RunCheck:
    """Which run a checked report is about."""

    seconds: float  # simulated time the run reached
    frames: int = 0
    partial: bool = False  # checked while the run goes on (the app's live report)

    def to_dict(self) -> JSONObject:
        return {"seconds": self.seconds, "frames": self.frames, "partial": self.partial}

    @classmethod
    def from_dict(cls, data: Parsed) -> RunCheck:
        return cls(float(data.get("seconds", 0.0)), int(data.get("frames", 0)), bool(data.get("partial", False)))


@dataclass(frozen=True)
class RunLength:
    """How long a run of the scenario should be (generation/run_length.py): `needed`, the longest time a
    planned claim needs (`by` says whose), with a margin, capped at `cap`."""

    seconds: float
    needed: float
    cap: float
    by: str = ""

    @property
    def capped(self) -> bool:
        return self.needed > self.seconds

    def to_dict(self) -> JSONObject:
        return {"seconds": self.seconds, "needed": self.needed, "cap": self.cap, "by": self.by}

    @classmethod
    def from_dict(cls, data: Parsed) -> RunLength:
        return cls(float(data.get("seconds", 0.0)), float(data.get("needed", 0.0)), float(data.get("cap", 0.0)),
                   str(data.get("by", "")))

    def line(self) -> str:
        text = f"run length: {self.seconds:.0f} s"
        if self.by:
            text += f" (the planned behaviours need {self.needed:.0f} s, longest {self.by}"
            text += f"; capped at {self.cap:.0f} s)" if self.capped else ", with a margin)"
        return text


@dataclass(frozen=True)
class GroundingReport:
    prompt: str
    groups: tuple[GroupGrounding, ...]
    unhonoured: tuple[str, ...] = ()  # parts of the sentence the scenario could not honour, said plainly
    repairs: tuple[str, ...] = field(default=())  # where the model's draft was repaired to match the sentence
    # Misspelt place words the reading put right ("read 'kitchn' as 'kitchen'"): honoured, but said,
    # so a user sees which place a typo was taken for. They do not make the report fail.
    corrections: tuple[str, ...] = field(default=())
    robot: RobotGrounding | None = None
    unsure: tuple[str, ...] = ()  # every question about the reading ("'the big meeting room': the boardroom?")
    run: RunCheck | None = None  # None: planned (before any run); else the run the claims were checked on
    # Every sentence the scenario was made from: the prompt, then each follow-up that refined it
    # (generation/refine.py); empty for a scenario of one sentence.
    sentences: tuple[str, ...] = ()
    length: RunLength | None = None  # how long a run should be for every claim to be told (planned)

    @property
    def checked(self) -> bool:
        return self.run is not None

    def _rows(self) -> list[str]:
        """Verdicts of the groups and of the robot (when the sentence asks something of it)."""
        robot = [self.robot.status] if self.robot is not None and self.robot.claims else []
        return [g.status for g in self.groups] + robot

    @property
    def status(self) -> str:
        rows = self._rows()
        if self.unhonoured or FAILS in rows or (not self.groups and self.run is not None):
            return FAILS
        if rows and all(s == HOLDS for s in rows):
            return HOLDS
        return UNCHECKED if UNCHECKED in rows else PLANNED

    @property
    def ok(self) -> bool:
        """Checked on a run, every group and the robot hold, nothing unhonoured."""
        return self.status == HOLDS

    def to_dict(self) -> JSONObject:
        data: JSONObject = {"prompt": self.prompt, "status": self.status, "ok": self.ok,
                            "groups": [g.to_dict() for g in self.groups],
                            "unhonoured": list(self.unhonoured), "repairs": list(self.repairs),
                            "corrections": list(self.corrections),
                            "robot": self.robot.to_dict() if self.robot is not None else None,
                            "unsure": list(self.unsure)}
        data["run"] = self.run.to_dict() if self.run is not None else None
        if self.sentences:
            data["sentences"] = list(self.sentences)
        if self.length is not None:
            data["length"] = self.length.to_dict()
        return data

    @classmethod
    def from_dict(cls, data: Parsed) -> GroundingReport:
        robot = data.get("robot")
        run = data.get("run")
        return cls(str(data.get("prompt", "")), tuple(GroupGrounding.from_dict(g) for g in data.get("groups", ())),
                   tuple(str(u) for u in data.get("unhonoured", ())), tuple(str(r) for r in data.get("repairs", ())),
                   tuple(str(c) for c in data.get("corrections", ())),
                   RobotGrounding.from_dict(robot) if robot else None, tuple(str(u) for u in data.get("unsure", ())),
                   RunCheck.from_dict(run) if run else None, tuple(str(s) for s in data.get("sentences", ())),
                   RunLength.from_dict(data["length"]) if data.get("length") else None)

    def counts(self) -> dict[str, int]:
        """Groups (and the robot) per verdict: {"holds": 3, "fails": 1, ...}."""
        rows = self._rows()
        return {s: rows.count(s) for s in STATUSES if rows.count(s)}

    def summary(self) -> str:
        """One line: 'planned: 3 groups and the robot' or '2/3 groups ✓, 1 ✗ (run of 60 s)'."""
        n = len(self.groups)
        asks_robot = self.robot is not None and bool(self.robot.claims)
        noun = f"{n} group{'s' if n != 1 else ''}" + (" and the robot" if asks_robot else "")
        if self.run is None:
            failing = sum(1 for g in self.groups if g.status == FAILS)
            return f"planned: {noun}" + (f", {failing} {FAIL_MARK} already" if failing else "")
        groups = [g.status for g in self.groups]
        text = f"{groups.count(HOLDS)}/{n} groups {OK_MARK}"
        if groups.count(FAILS):
            text += f", {groups.count(FAILS)} {FAIL_MARK}"
        if groups.count(UNCHECKED) or groups.count(PLANNED):
            text += f", {groups.count(UNCHECKED) + groups.count(PLANNED)} not checked"
        if asks_robot and self.robot is not None:
            text += f"; robot {MARKS[self.robot.status]}"
        when = "so far" if self.run.partial else "run"
        shorter = ""
        if self.length is not None and not self.run.partial and self.run.seconds + 1.0 < self.length.seconds:
            shorter = f"; the scenario's length is {self.length.seconds:.0f} s"
        return f"{text} ({when} of {self.run.seconds:.0f} s{shorter})"

    def lines(self) -> list[str]:
        """Plain-text rendering, one line per group and one per claim (for the CLI and logs)."""
        out: list[str] = [self.summary()]
        if self.length is not None:
            out.append(self.length.line())
        for number, sentence in enumerate(self.sentences, start=1):
            out.append(f"sentence {number}: {sentence}")
        for g in self.groups:
            asked = f", {g.asked()}" if self.sentences else ""
            out.append(f"{MARKS[g.status]} {g.who} -> {g.label} ({len(g.members)} agents{asked})")
            if g.edit:
                out.append(f"    ! {g.edit}")
            for c in g.claims:
                out.append("    " + claim_line(c))
            for a in g.added:
                out.append(f"    + added: {a}")
            for q in g.unsure:
                out.append(f"    ? unsure: {q}")
        if self.robot is not None:
            r = self.robot
            if r.claims:
                out.append(f"{MARKS[r.status]} robot: {r.task} ('{r.text}')" + (f": {r.plan}" if r.plan else ""))
            else:
                out.append(f"- robot: {r.plan or 'not asked'}")
            for c in r.claims:
                out.append("    " + claim_line(c))
            for q in r.unsure:
                out.append(f"    ? unsure: {q}")
        for correction in self.corrections:
            out.append(f"~ correction: {correction}")
        for u in self.unhonoured:
            out.append(f"{FAIL_MARK} not honoured: {u}")
        return out


def claim_line(c: Claim) -> str:
    line = f"{c.mark} {c.kind.replace('_', ' ')}: asked {c.asked}, {c.status}"
    line += f": {c.evidence}" if c.evidence else f" ({c.plan})" if c.plan else ""
    return line


def planned(claims: list[Claim]) -> tuple[Claim, ...]:
    """Claims of a plan: none is ✓ before a run (a ✗ the plan already shows stays)."""
    return tuple(c if c.status in (PLANNED, FAILS) else replace(c, status=PLANNED, evidence="") for c in claims)
