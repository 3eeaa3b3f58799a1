"""The understanding suite's scorer: how well a prompt's reading, and the scenario built from it,
match what the sentence says.

Cases come from `eval/understanding/cases.yaml` (built by `eval/understanding/build.py`): a prompt,
a world and the expected reading (see the file's header). Two levels are scored:

- the reading (`grove_tui.language.reading.read_prompt`, no model, milliseconds per prompt), field by
  field for every expected group: groups found, count, intent, places by role (start, destination,
  location, via), robot interaction and reaction, together, pace, wait, purpose, relation, a sane
  label; and per case the unknown places: a refusal where one is expected, none where not;
- for a sample of cases, the final scenario written with the embedded model: head count, start and
  destination zones, the stationary groups' zones, behavior (robot reaction) types, idle agents (a
  tree with no action node: it only checks conditions, so the person never moves).

Expected groups are matched to the reading's groups in sentence order; when the numbers differ the
order-preserving assignment that agrees on most fields is used, and an expected group with no match
fails every one of its fields.
"""

from __future__ import annotations

import csv
import io
import itertools
import json
import time
import unicodedata
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

import yaml

from grove_tui.bt.format.document import TreeDocument
from grove_tui.errors import GroveError, UnderstandingError
from grove_tui.language.lexicon import SCALES, TENS, UNITS

# A label is never a number: the lexicon's number words (not "couple" or "pair", which name people).
NUMBER_WORDS = frozenset(UNITS) | frozenset(TENS) | frozenset(SCALES)

if TYPE_CHECKING:
    from grove_tui.scenario.model import Scenario
    from grove_tui.world.model import World

# A PromptReading's to_dict(): JSON, compared field by field with what the suite's YAML states.
ReadingDict = Mapping[str, Any]  # Any: to_dict()'s JSON or the suite's YAML, compared key by key
# Reads a prompt in a world with a seed: the reader under test (language.reading.read_prompt by default).
Reader = Callable[[str, "World", int], ReadingDict]

PLACE_ROLES = ("start", "destination", "location", "via")
GROUP_FIELDS = ("count", "intent", *PLACE_ROLES, "places", "robot_interaction", "robot_reaction", "together",
                "pace", "wait_seconds", "purpose", "relation", "label")
CASE_FIELDS = ("groups", "unknown_place_refusals", "false_refusals", "robot_task", "robot_places")
# The thresholds: each of these at >= 95 %, and no false refusal of a place the world has.
THRESHOLD_FIELDS = ("groups", "count", "intent", "places", "robot_reaction")
THRESHOLD = 0.95
SCENARIO_FIELDS = ("agent_count", "start_zones", "destination_zones", "location_zones", "behavior_types",
                   "no_idle_agents")


@dataclass(frozen=True)
class UnderstandingCase:
    id: str
    world: str
    preset: str
    cls: str
    prompt: str
    groups: tuple[dict, ...]
    unknown_places: tuple[str, ...] = ()
    seed: int = 0
    # What the sentence asks of the robot itself ({task, start, destination, location, via}); None:
    # it asks nothing of the robot. Scored only when the case states it (`robot_stated`).
    robot: dict | None = None
    robot_stated: bool = False


def load_cases(path: str | Path) -> list[UnderstandingCase]:
    path = Path(path)
    try:
        data = yaml.safe_load(path.read_text(encoding="utf-8"))
    except FileNotFoundError:
        raise UnderstandingError(f"{path}: no such cases file") from None
    except yaml.YAMLError as exc:
        raise UnderstandingError(f"{path}: not valid YAML: {exc}") from None
    if not isinstance(data, dict) or not isinstance(data.get("cases"), list):
        raise UnderstandingError(f"{path}: expected a mapping with a `cases` list")
    cases = []
    for index, raw in enumerate(data["cases"]):
        try:
            expect = raw["expect"]
            cases.append(UnderstandingCase(
                id=str(raw["id"]), world=str(raw["world"]), preset=str(raw.get("preset", "normal")),
                cls=str(raw.get("class", "")), prompt=str(raw["prompt"]),
                groups=tuple(dict(g) for g in expect["groups"]),
                unknown_places=tuple(expect.get("unknown_places") or ()), seed=int(raw.get("seed", 0)),
                robot=dict(expect["robot"]) if expect.get("robot") else None, robot_stated="robot" in expect))
        except (KeyError, TypeError, ValueError) as exc:
            raise UnderstandingError(f"{path}: cases[{index}]: missing or malformed {exc}") from None
        _check_values(path, index, cases[-1])
    ids = [c.id for c in cases]
    if len(ids) != len(set(ids)):
        raise UnderstandingError(f"{path}: case ids repeat")
    return cases


def _check_values(path: Path, index: int, case: UnderstandingCase) -> None:
    """An intent or robot task the reader can never give is a typo in the cases, not a miss of the reader:
    say so when the file loads, instead of scoring it as a wrong reading."""
    from grove_tui.language.model import INTENTS, ROBOT_TASKS

    for number, group in enumerate(case.groups):
        if "intent" in group and group["intent"] not in INTENTS:
            raise UnderstandingError(f"{path}: cases[{index}] ({case.id}): group {number}: intent "
                                     f"{group['intent']!r} is not one of {', '.join(INTENTS)}")
    if case.robot and "task" in case.robot and case.robot["task"] not in ROBOT_TASKS:
        raise UnderstandingError(f"{path}: cases[{index}] ({case.id}): robot task {case.robot['task']!r} is not "
                                 f"one of {', '.join(ROBOT_TASKS)}")


# --- the reading -----------------------------------------------------------------------------------


@dataclass
class ReadingScore:
    case: UnderstandingCase
    checks: dict[str, list[bool]] = field(default_factory=dict)  # field -> one bool per scored item
    misses: list[str] = field(default_factory=list)  # "field: expected X, read Y" for every failure
    seconds: float = 0.0
    error: str = ""

    def add(self, name: str, ok: bool, detail: str = "") -> None:
        self.checks.setdefault(name, []).append(bool(ok))
        if not ok:
            self.misses.append(f"{name}: {detail}" if detail else name)


def _count_ok(expected: Mapping, got: Mapping | None) -> tuple[bool, str]:
    if not got:
        return False, "no count"
    kinds = expected.get("kind")
    kinds = [kinds] if isinstance(kinds, str) else list(kinds or [])
    value = got.get("value")
    problems = []
    if kinds and got.get("kind") not in kinds:
        problems.append(f"kind {got.get('kind')!r} not in {kinds}")
    if "value" in expected and value != expected["value"]:
        problems.append(f"value {value} != {expected['value']}")
    if "range" in expected:
        low, high = expected["range"]
        if not isinstance(value, (int, float)) or not low <= value <= high:
            problems.append(f"value {value} outside [{low}, {high}]")
    for key in ("parties", "party_size"):
        if key in expected and got.get(key) != expected[key]:
            problems.append(f"{key} {got.get(key)} != {expected[key]}")
    return not problems, "; ".join(problems)


def _label_ok(label: object, node_names: frozenset[str]) -> bool:
    if not isinstance(label, str) or not label.strip():
        return False
    words = label.lower().replace("-", " ").split()
    return not (set(words) & NUMBER_WORDS) and not any(w.isdigit() for w in words) and label not in node_names


def _group_checks(expected: Mapping, got: Mapping | None, node_names: frozenset[str]) -> list[tuple[str, bool, str]]:
    """(field, ok, detail) for every field the expected group states, and for its places together."""
    checks: list[tuple[str, bool, str]] = []

    def check(name: str, ok: bool, want: object, have: object) -> None:
        checks.append((name, ok, f"expected {want!r}, read {have!r}"))

    if got is None:
        for name in GROUP_FIELDS:
            if name in expected or (name == "places" and any(r in expected for r in PLACE_ROLES)) \
                    or name == "label":
                checks.append((name, False, "group not found"))
        return checks
    if "count" in expected:
        ok, detail = _count_ok(expected["count"], got.get("count"))
        checks.append(("count", ok, detail))
    for name in ("intent", "robot_interaction", "robot_reaction", "together", "pace", "relation"):
        if name in expected:
            check(name, got.get(name) == expected[name], expected[name], got.get(name))
    places_ok = True
    stated_places = False
    for role in PLACE_ROLES:
        if role not in expected:
            continue
        stated_places = True
        want, have = expected[role], got.get(role)
        ok = _vias(want) == _vias(have) if role == "via" else have == want
        places_ok &= ok
        check(role, ok, want, have)
    if stated_places:
        checks.append(("places", places_ok, "a place role differs"))
    if "wait_seconds" in expected:
        want, have = expected["wait_seconds"], got.get("wait_seconds")
        ok = (want is None and have is None) or (
            want is not None and isinstance(have, (int, float)) and abs(float(have) - float(want)) < 0.5)
        check("wait_seconds", ok, want, have)
    if "purpose" in expected:
        have = got.get("purpose") or ""
        check("purpose", expected["purpose"] in str(have).lower(), expected["purpose"], have)
    check("label", _label_ok(got.get("label"), node_names), "a noun, not a number or node name", got.get("label"))
    return checks


def _align(expected: Sequence[Mapping], got: Sequence[Mapping], node_names: frozenset[str]) -> list[int | None]:
    """For each expected group the index of its reading group (None: not found), order preserved."""
    if len(expected) == len(got):
        return list(range(len(expected)))
    best: tuple[int, list[int | None]] = (-1, [None] * len(expected))
    if len(got) < len(expected):
        # Which expected groups the reading found: try every order-preserving choice.
        for chosen in itertools.combinations(range(len(expected)), len(got)):
            mapping: list[int | None] = [None] * len(expected)
            for reading_index, expected_index in enumerate(chosen):
                mapping[expected_index] = reading_index
            agree = sum(ok for e, m in zip(expected, mapping) if m is not None
                        for _, ok, _ in _group_checks(e, got[m], node_names))
            best = max(best, (agree, mapping), key=lambda pair: pair[0])
        return best[1]
    for chosen in itertools.combinations(range(len(got)), len(expected)):
        agree = sum(ok for e, m in zip(expected, chosen) for _, ok, _ in _group_checks(e, got[m], node_names))
        best = max(best, (agree, list[int | None](chosen)), key=lambda pair: pair[0])
    return best[1]


def _plain(text: str) -> str:
    """Lower case without accents: the reader writes "café" as "cafe"."""
    return unicodedata.normalize("NFKD", text).encode("ascii", "ignore").decode("ascii").lower()


def score_reading(case: UnderstandingCase, reading: ReadingDict, node_names: frozenset[str] = frozenset()
                  ) -> ReadingScore:
    """Score one reading (the `to_dict()` of a PromptReading) against the case's expectation."""
    score = ReadingScore(case)
    got = list(reading.get("groups") or [])
    unknown = [_plain(str(u)) for u in reading.get("unknown_places") or ()]
    if case.unknown_places:
        # A refusal is right only when it names the missing place (its head noun is enough; "café" is "cafe").
        named = all(any(_plain(place.split()[-1]) in u for u in unknown) for place in case.unknown_places)
        score.add("unknown_place_refusals", named, f"expected {list(case.unknown_places)}, read {unknown}")
        return score  # the groups of a sentence that is refused are not scored
    score.add("false_refusals", not unknown, f"refused places the world has: {unknown}")
    score.add("groups", len(got) == len(case.groups), f"expected {len(case.groups)} groups, read {len(got)}")
    mapping = _align(case.groups, got, node_names)
    for number, (expected, index) in enumerate(zip(case.groups, mapping)):
        for name, ok, detail in _group_checks(expected, None if index is None else got[index], node_names):
            score.add(name, ok, f"group {number}: {detail}")
    if case.robot_stated:
        _score_robot(score, case.robot, reading.get("robot"))
    return score


def _score_robot(score: ReadingScore, expected: ReadingDict | None, got: ReadingDict | None) -> None:
    """The robot's own clause: its task, and its places by role (those the case states)."""
    if expected is None:
        score.add("robot_task", got is None, f"expected no robot task, read {got!r}")
        return
    have = got or {}
    score.add("robot_task", have.get("task") == expected.get("task"),
              f"expected {expected.get('task')!r}, read {have.get('task')!r}")
    roles = [r for r in PLACE_ROLES if r in expected]
    if roles:
        wrong = [f"{r}: expected {expected[r]!r}, read {have.get(r)!r}" for r in roles
                 if (_vias(expected[r]) != _vias(have.get(r)) if r == "via" else have.get(r) != expected[r])]
        score.add("robot_places", not wrong, "; ".join(wrong))


def default_reader() -> Reader:
    from grove_tui.language.reading import read_prompt

    return lambda prompt, world, seed: read_prompt(prompt, world, seed=seed).to_dict()


def run_reading(cases: Sequence[UnderstandingCase],
                reader: Reader | None = None) -> list[ReadingScore]:
    """Read every case's prompt and score it; a reader exception is a failed case, not a crash."""
    from grove_tui.bt.format.manifest import NODES
    from grove_tui.world import load_world

    reader = reader or default_reader()
    node_names = frozenset(NODES)
    worlds: dict[str, World] = {}
    scores = []
    for case in cases:
        if case.world not in worlds:
            try:
                worlds[case.world] = load_world(case.world)
            except GroveError as exc:
                raise UnderstandingError(f"case {case.id}: {exc}", hint="Cases name shipped worlds.") from None
        started = time.perf_counter()
        try:
            reading = reader(case.prompt, worlds[case.world], case.seed)
        except Exception as exc:  # noqa: BLE001 - a crash on one sentence is that case's failure
            score = ReadingScore(case, error=f"{type(exc).__name__}: {exc}")
            for name in ("groups", "count", "intent", "places", "robot_reaction"):
                score.add(name, False, score.error)
        else:
            score = score_reading(case, reading, node_names)
        score.seconds = time.perf_counter() - started
        scores.append(score)
    return scores


def summarize_reading(scores: Sequence[ReadingScore]) -> dict[str, tuple[int, int]]:
    """field -> (passed, scored); false_refusals counts the cases *with* a false refusal."""
    table: dict[str, tuple[int, int]] = {}
    for name in CASE_FIELDS + GROUP_FIELDS:
        values = [ok for s in scores for ok in s.checks.get(name, ())]
        if name == "false_refusals":
            table[name] = (sum(not ok for ok in values), len(values))
        elif values:
            table[name] = (sum(values), len(values))
    return table


def below_threshold(table: Mapping[str, tuple[int, int]]) -> list[str]:
    """The issue's must-show fields that miss their bar, as readable lines (empty: all pass)."""
    lines = []
    for name in THRESHOLD_FIELDS:
        passed, total = table.get(name, (0, 0))
        if total == 0 or passed / total < THRESHOLD:
            lines.append(f"{name} {passed}/{total} = {passed / max(total, 1):.1%} < {THRESHOLD:.0%}")
    refusals, total = table.get("false_refusals", (0, 0))
    if refusals:
        lines.append(f"false unknown-place refusals {refusals}/{total} (must be 0)")
    return lines


# --- the scenario ----------------------------------------------------------------------------------


@dataclass
class ScenarioScore:
    case: UnderstandingCase
    checks: dict[str, bool | None] = field(default_factory=dict)  # None: the case states nothing to check
    misses: list[str] = field(default_factory=list)
    agents: int = 0
    idle_agents: int = 0
    seconds: float = 0.0
    error: str = ""

    def set(self, name: str, ok: bool | None, detail: str = "") -> None:
        self.checks[name] = ok
        if ok is False:
            self.misses.append(f"{name}: {detail}")


def expected_total(groups: Sequence[Mapping]) -> tuple[int, int]:
    """The scenario's head count range: every group, less members of subsets ("one of them")."""
    low = high = 0
    for expected in groups:
        count = expected.get("count", {})
        lo, hi = (count["range"] if "range" in count else (count.get("value", 0), count.get("value", 0)))
        if str(expected.get("relation", "")).startswith("subset_of"):
            continue  # already counted in its parent
        low, high = low + int(lo), high + int(hi)
    return low, high


def _zone_of(world: World, name: str) -> str | None:
    try:
        place = world.find(name)
    except GroveError:
        return None
    return name if hasattr(place, "boundary") else getattr(place, "zone", None)


def idle_tree(document: TreeDocument, action_names: frozenset[str]) -> bool:
    """A tree whose nodes include no action: it can only check conditions, so nobody moves."""
    node_types = {el.id for el in document.nodes()}  # compact <GoTo/> and explicit <Action ID="GoTo"/>
    return not (node_types & action_names)


def score_scenario(case: UnderstandingCase, world: World, scenario: Scenario, trees: Mapping[str, TreeDocument],
                   action_names: frozenset[str]) -> ScenarioScore:
    """Score a generated scenario (Scenario plus its trees by relative path) against the case."""
    score = ScenarioScore(case, agents=len(scenario.agents))
    low, high = expected_total(case.groups)
    score.set("agent_count", low <= len(scenario.agents) <= high,
              f"{len(scenario.agents)} agents, expected {low}..{high}")
    starts = set()
    for agent in scenario.agents:
        zone = world.zone_at(*agent.start)
        starts.add(zone.name if zone is not None else None)
    heading = {agent.zone for agent in scenario.agents}
    for name, role, where in (("start_zones", "start", starts), ("destination_zones", "destination", heading),
                              ("location_zones", "location", heading)):
        wanted = [_zone_of(world, g[role]) for g in case.groups if g.get(role)]
        if not wanted:
            score.set(name, None)
            continue
        if role == "location":
            where = heading | starts  # a stationary group is where it stands, whether it walked there or not
        missing = [w for w in wanted if w not in where]
        score.set(name, not missing, f"no agent for {missing} (have {sorted(z for z in where if z)})")
    wanted_behaviors = {g["robot_reaction"] for g in case.groups if g.get("robot_reaction")}
    have_behaviors = {a.behavior for a in scenario.agents if a.behavior not in ("Regular", "Impassive")}
    score.set("behavior_types", wanted_behaviors == have_behaviors,
              f"expected {sorted(wanted_behaviors)}, scenario has {sorted(have_behaviors)}")
    score.idle_agents = sum(idle_tree(trees[a.tree], action_names) for a in scenario.agents)
    score.set("no_idle_agents", score.idle_agents == 0, f"{score.idle_agents} agents with no action in their tree")
    return score


# The order classes enter a scenario sample: what the must-show depends on first.
SAMPLE_PRIORITY = ("compound_2", "robot_look", "evacuate", "queue", "robot_approach", "purpose", "wait_duration",
                   "robot_avoid", "subset", "others", "robot_block", "structured", "whole_zone", "exclusive",
                   "robot_follow", "pace", "compound_3", "together", "vague_count", "negation", "converse", "wander",
                   "evacuate_compound", "more", "follow", "walk", "via", "approximate_count", "wait")


def sample_cases(cases: Sequence[UnderstandingCase], n: int) -> list[UnderstandingCase]:
    """N cases over as many classes as N allows (SAMPLE_PRIORITY order, then any other class), the
    world rotating from class to class and round to round; refusals are left out (a refused prompt
    builds no scenario). Deterministic: the same suite gives the same sample."""
    pool = [c for c in cases if not c.unknown_places]
    if n <= 0 or not pool:
        return []
    by_class: dict[str, dict[str, list[UnderstandingCase]]] = {}
    for case in pool:
        by_class.setdefault(case.cls, {}).setdefault(case.world, []).append(case)
    order = [c for c in SAMPLE_PRIORITY if c in by_class] + sorted(set(by_class) - set(SAMPLE_PRIORITY))
    worlds = sorted({c.world for c in pool})
    chosen: list[UnderstandingCase] = []
    taken: set[str] = set()
    for round_index in range(len(pool)):
        for class_index, cls in enumerate(order):
            if len(chosen) >= n:
                return chosen
            in_worlds = by_class[cls]
            for shift in range(len(worlds)):
                world = worlds[(class_index + round_index + shift) % len(worlds)]
                options = [c for c in in_worlds.get(world, []) if c.id not in taken]
                if options:
                    chosen.append(options[0])
                    taken.add(options[0].id)
                    break
    return chosen


def summarize_scenarios(scores: Sequence[ScenarioScore]) -> dict[str, tuple[int, int]]:
    table = {}
    for name in SCENARIO_FIELDS:
        values = [s.checks.get(name) for s in scores if s.checks.get(name) is not None]
        table[name] = (sum(bool(v) for v in values), len(values))
    return table


# --- results ---------------------------------------------------------------------------------------


def _pct(passed: int, total: int) -> str:
    return f"{100.0 * passed / total:.1f} %" if total else "n/a"


def results_markdown(reading: Sequence[ReadingScore], scenarios: Sequence[ScenarioScore], command: str = "") -> str:
    table = summarize_reading(reading)
    lines = ["# Understanding suite results", ""]
    if command:
        lines += ["```", command, "```", ""]
    worlds = sorted({s.case.world for s in reading})
    lines += [f"{len(reading)} prompts over {len(worlds)} worlds ({', '.join(worlds)}); the reading needs no model.",
              "", "## The reading", "", "| field | passed | scored | share | bar |", "|---|---:|---:|---:|---|"]
    for name, (passed, total) in table.items():
        if name == "false_refusals":
            lines.append(f"| false unknown-place refusals (cases) | {passed} | {total} | {_pct(passed, total)} "
                         f"| {'ok' if passed == 0 else 'FAIL'} (must be 0) |")
            continue
        bar = ""
        if name in THRESHOLD_FIELDS:
            bar = "ok" if total and passed / total >= THRESHOLD else "FAIL"
            bar += f" (>= {THRESHOLD:.0%})"
        lines.append(f"| {name} | {passed} | {total} | {_pct(passed, total)} | {bar} |")
    seconds = sorted(s.seconds for s in reading)
    if seconds:
        lines += ["", f"Reading time per prompt: median {1000 * seconds[len(seconds) // 2]:.1f} ms, "
                      f"max {1000 * seconds[-1]:.1f} ms."]
    by_class: dict[str, list[bool]] = {}
    for s in reading:
        by_class.setdefault(s.case.cls, []).append(not s.misses)
    lines += ["", "Cases read entirely right, by class:", "", "| class | right | cases |", "|---|---:|---:|"]
    lines += [f"| {cls} | {sum(v)} | {len(v)} |" for cls, v in sorted(by_class.items())]
    if scenarios:
        lines += ["", "## The scenario (embedded model)", "",
                  f"{len(scenarios)} cases spread over the suite, generated with the local model.", "",
                  "| check | passed | scored | share |", "|---|---:|---:|---:|"]
        for name, (passed, total) in summarize_scenarios(scenarios).items():
            lines.append(f"| {name} | {passed} | {total} | {_pct(passed, total)} |")
        idle = sum(s.idle_agents for s in scenarios)
        agents = sum(s.agents for s in scenarios)
        lines += ["", f"Idle agents (a tree with no action node): {idle} of {agents}.",
                  f"Seconds per scenario: mean {sum(s.seconds for s in scenarios) / len(scenarios):.1f}."]
        failed = [s for s in scenarios if s.error]
        if failed:
            lines += ["", "Failed generations:", ""] + [f"- {s.case.id}: {s.error}" for s in failed]
    misses = [(s.case.id, s.case.prompt, m) for s in reading for m in s.misses[:3]]
    if misses:
        lines += ["", "## First misses of the reading", ""]
        lines += [f"- `{cid}` {prompt!r}: {miss}" for cid, prompt, miss in misses[:40]]
    return "\n".join(lines) + "\n"


def results_csv(reading: Sequence[ReadingScore], scenarios: Sequence[ScenarioScore]) -> str:
    """One row per case: each reading field's passed/scored, the scenario checks (1/0/blank), the misses."""
    by_case = {s.case.id: s for s in scenarios}
    reading_fields = [f for f in CASE_FIELDS + GROUP_FIELDS if any(f in s.checks for s in reading)]
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(["case", "world", "class", "prompt", *reading_fields, "reading_seconds",
                     *[f"scenario_{f}" for f in SCENARIO_FIELDS], "scenario_agents", "scenario_idle_agents",
                     "misses"])
    for s in reading:
        cells = []
        for name in reading_fields:
            values = s.checks.get(name)
            cells.append("" if not values else f"{sum(values)}/{len(values)}")
        sc = by_case.get(s.case.id)
        scenario_cells = ["" if sc is None or sc.checks.get(f) is None else int(bool(sc.checks[f]))
                          for f in SCENARIO_FIELDS]
        scenario_cells += ["", ""] if sc is None else [sc.agents, sc.idle_agents]
        misses = s.misses + ([] if sc is None else [f"scenario {m}" for m in sc.misses])
        writer.writerow([s.case.id, s.case.world, s.case.cls, s.case.prompt, *cells, f"{s.seconds:.4f}",
                         *scenario_cells, " | ".join(misses)])
    return buffer.getvalue()


def write_results(reading: Sequence[ReadingScore], scenarios: Sequence[ScenarioScore], out_dir: str | Path,
                  command: str = "") -> list[Path]:
    from grove_tui.files import write_text_atomic

    out = Path(out_dir)
    paths = [write_text_atomic(out / "results.csv", results_csv(reading, scenarios)),
             write_text_atomic(out / "RESULTS.md", results_markdown(reading, scenarios, command))]
    summary = {"reading": {k: list(v) for k, v in summarize_reading(reading).items()},
               "scenario": {k: list(v) for k, v in summarize_scenarios(scenarios).items()} if scenarios else {}}
    paths.append(write_text_atomic(out / "summary.json", json.dumps(summary, indent=2) + "\n"))
    return paths


__all__ = ["UnderstandingCase", "UnderstandingError", "load_cases", "score_reading", "run_reading",
           "summarize_reading", "below_threshold", "score_scenario", "sample_cases",
           "summarize_scenarios", "write_results", "results_markdown", "results_csv", "expected_total",
           "idle_tree"]


def _vias(value: object) -> list[str]:
    """A via as a sorted list of names: a case may write one place as a name ("via: workshop"), which
    sorted() would split into letters."""
    if value is None:
        return []
    if isinstance(value, (list, tuple)):
        return sorted(str(v) for v in value)
    return [str(value)]
