"""Hypothesis strategies and targets for fuzzing every parser GROVE exposes to user files.

Shared by tests/test_fuzz.py (a bounded run in CI) and bench/fuzz.py (minutes per parser, by hand).
A target takes one generated input and exercises the parser the way the product does; the only
acceptable failure is a GroveError (the message a user sees). Anything else is a bug.

Inputs are mutations of valid seeds (so they get past the first checks and reach deep code) plus
structured values of the wrong shapes (so type checks are exercised): the tokens inserted are the
ones the hostile-input review used (aliases, anchors, deep brackets, huge and non-finite numbers,
Python tags, entities, paths that escape, NUL bytes).
"""

from __future__ import annotations

import json
import os
import tempfile
from collections.abc import Callable
from contextlib import contextmanager
from pathlib import Path
from typing import Any

import yaml
from hypothesis import strategies as st

from grove_tui.paths import worlds_dir

HOSTILE_TOKENS = [
    "*a", "&a ", "&a [*a]", "[", "]", "{", "}", ":", ": ", "- ", "\n", "\n  ", "  ", ",", "? ", "!!python/object/apply:os.system ['true']",
    "!!binary AAAA", "1e400", "1.0e400", "9" * 400, "9" * 5000, ".nan", "-.inf", ".inf", "~", "null", "'", '"', "\t", "\x00",
    "<", ">", "&", "</", "/>", "<!DOCTYPE r [<!ENTITY e SYSTEM 'file:///etc/passwd'>]>", "&e;", "<xi:include href='/etc/passwd'/>",
    "../", "../../etc/passwd", "/dev/zero", "0", "-1", "-0", "true", "no", "ünïcödé", "🔥", "0x1F", "1_000", "2020-13-45",
    "[" * 60, "]" * 60, "{{", "}}", "\\", "%", "#", "|", ">-",
]

json_values = st.recursive(
    st.none() | st.booleans() | st.integers(min_value=-(10**30), max_value=10**30)
    | st.floats(allow_nan=True, allow_infinity=True) | st.text(max_size=12) | st.sampled_from(HOSTILE_TOKENS),
    lambda children: st.lists(children, max_size=4) | st.dictionaries(st.text(max_size=10), children, max_size=4),
    max_leaves=24,
)


def _apply_edits(base: str, edits: list[tuple[int, int, str]]) -> str:
    text = base
    for position, delete, insert in edits:
        at = position % (len(text) + 1)
        text = text[:at] + insert + text[at + delete:]
    return text


def mutations_of(base: str, max_edits: int = 6) -> st.SearchStrategy[str]:
    """`base` with a few random replacements, deletions and insertions of hostile tokens or any text."""
    edit = st.tuples(st.integers(min_value=0, max_value=max(len(base), 1) * 4), st.integers(min_value=0, max_value=12),
                     st.sampled_from(HOSTILE_TOKENS) | st.text(max_size=6))
    return st.lists(edit, min_size=1, max_size=max_edits).map(lambda edits: _apply_edits(base, edits))


@contextmanager
def temporary_file(data: str | bytes, name: str):
    with tempfile.TemporaryDirectory(prefix="grove-fuzz-") as folder:
        path = Path(folder) / name
        path.write_bytes(data if isinstance(data, bytes) else data.encode("utf-8", errors="surrogatepass"))
        yield path


# -- seeds ---------------------------------------------------------------------------------------

WORLD_SEED = (worlds_dir() / "residential.yaml").read_text(encoding="utf-8")

TREE_SEED = """<root BTCPP_format="4" main_tree_to_execute="agent_1">
  <BehaviorTree ID="agent_1">
    <Sequence>
      <GoTo target="pharmacy_counter" x="30.5" y="6.2" goal_id="7" waypoints="28.0,5.0;29.0,6.0"/>
      <Queue service_point="pharmacy_counter" x="30.5" y="6.2" spacing="0.6" service_time="8"/>
      <SubTree ID="leave"/>
    </Sequence>
  </BehaviorTree>
  <BehaviorTree ID="leave">
    <FollowVelocityField exit="main_entrance" field="group_1"/>
  </BehaviorTree>
</root>
"""

SCENARIO_SEED: dict[str, Any] = {
    "world": "hospital", "preset": "emergency", "prompt": "ten patients leave", "seed": 3, "models": {"bt": "m.gguf"},
    "agents": [{"id": 1, "group": 0, "start": [30.0, 5.0], "goals": [[31.0, 6.0], [40.0, 2.0]], "zone": "pharmacy",
                "tree": "trees/agent_1.xml", "radius": 0.35, "max_vel": 1.2, "label": "patients", "behavior": "Regular"},
               {"id": 2, "group": -1, "start": [32.0, 5.0], "goals": [], "zone": "pharmacy",
                "tree": "trees/agent_2.xml", "radius": 0.3, "max_vel": 1.0, "label": "patients", "behavior": "Scared"}],
    "robot": {"start": [28.0, 4.0], "goal": [45.0, 5.0], "radius": 0.3, "max_vel": 0.8, "path": [[28.0, 4.0], [45.0, 5.0]]},
    "fields": {"group_1": "fields/group_1.npz"}, "resolution": 0.1,
}
SCENARIO_TEXT_SEED = yaml.safe_dump(SCENARIO_SEED, sort_keys=False, default_flow_style=None, width=120)

CONFIG_SEED = """ui:
  theme: dark
generation:
  seed: 3
simulation:
  seconds: 60
models:
  bt: /models/qwen.gguf
"""

BATCH_SEED = "\n".join(json.dumps(job) for job in (
    {"world": "hospital", "preset": "normal", "prompt": "ten visitors walk to the cafeteria", "seed": 1, "name": "a"},
    {"world": "office", "preset": "queuing", "prompt": "five people queue at the coffee machine", "simulate": 30},
)) + "\n"


def _scenario_variants() -> st.SearchStrategy[Any]:
    """The seed scenario with one key (top level or in an agent) replaced by an arbitrary value."""
    top = st.sampled_from(sorted(SCENARIO_SEED))
    agent_key = st.sampled_from(sorted(SCENARIO_SEED["agents"][0]))

    def replace_top(key_value):
        key, value = key_value
        data = json.loads(json.dumps(SCENARIO_SEED))
        data[key] = value
        return data

    def replace_agent(key_value):
        key, value = key_value
        data = json.loads(json.dumps(SCENARIO_SEED))
        data["agents"][0][key] = value
        return data

    return (st.tuples(top, json_values).map(replace_top) | st.tuples(agent_key, json_values).map(replace_agent)
            | json_values)


def _world_variants() -> st.SearchStrategy[str]:
    """Structured worlds: a zone whose keys hold arbitrary values, dumped as YAML."""
    zone = st.fixed_dictionaries({}, optional={key: json_values for key in
                                               ("name", "type", "boundary", "doors", "entities", "aliases", "tags")})
    world = st.fixed_dictionaries({"name": st.just("w") | json_values, "zones": st.lists(zone, max_size=3) | json_values},
                                  optional={"obstacles": json_values, "description": json_values})
    return world.map(lambda data: yaml.safe_dump(data, allow_unicode=True))


# -- targets ---------------------------------------------------------------------------------------


def fuzz_world(text: str) -> None:
    from grove_tui.world import parse_world

    world, problems = parse_world(text, "fuzz.yaml")
    assert (world is None) == bool(problems)
    for problem in problems:
        assert "\n" not in problem.message or problem.message.count("\n") < 3


def fuzz_world_file(data: str) -> None:
    from grove_tui.world import WorldError, load_world

    with temporary_file(data, "fuzz_world.yaml") as path:
        try:
            load_world(path)
        except WorldError:
            pass


def fuzz_tree(text: str) -> None:
    from grove_tui.bt.xml import check_tree_text, parse_tree_text

    check_tree_text(text, "fuzz.xml")
    parse_tree_text(text, "fuzz.xml")


def fuzz_scenario_dict(data: Any) -> None:
    from grove_tui.scenario.model import Scenario

    scenario = Scenario.from_dict(data, "fuzz.yaml")
    # What loads must survive its own round trip.
    assert Scenario.from_dict(yaml.safe_load(scenario.dump_yaml()), "again") == scenario


def fuzz_scenario_file(text: str) -> None:
    from grove_tui.scenario.bundle import load_scenario

    with tempfile.TemporaryDirectory(prefix="grove-fuzz-") as folder:
        Path(folder, "scenario.yaml").write_bytes(text.encode("utf-8", errors="surrogatepass"))
        load_scenario(folder)


def fuzz_config(text: str) -> None:
    from grove_tui.settings import load_settings

    with temporary_file(text, "config.yaml") as path:
        saved = os.environ.get("GROVE_CONFIG_FILE")
        os.environ["GROVE_CONFIG_FILE"] = str(path)
        try:
            load_settings()
        finally:
            if saved is None:
                os.environ.pop("GROVE_CONFIG_FILE", None)
            else:
                os.environ["GROVE_CONFIG_FILE"] = saved


def fuzz_batch(text: str) -> None:
    from grove_tui.services.jobs import read_jobs

    with temporary_file(text, "jobs.jsonl") as path:
        jobs, problems = read_jobs(path)
        names = [job.name.lower() for job in jobs]
        assert len(names) == len(set(names))  # duplicate names never both run


def fuzz_batch_lines(lines: list[Any]) -> None:
    fuzz_batch("\n".join(json.dumps(line) if not isinstance(line, str) else line for line in lines))


TARGETS: dict[str, tuple[st.SearchStrategy[Any], Callable[[Any], None]]] = {
    "world_text": (mutations_of(WORLD_SEED), fuzz_world),
    "world_structured": (_world_variants(), fuzz_world),
    "world_file": (mutations_of(WORLD_SEED) | st.binary(max_size=200).map(lambda b: b.decode("latin-1")), fuzz_world_file),
    "tree": (mutations_of(TREE_SEED) | st.text(max_size=200), fuzz_tree),
    "scenario_dict": (_scenario_variants(), fuzz_scenario_dict),
    "scenario_file": (mutations_of(SCENARIO_TEXT_SEED), fuzz_scenario_file),
    "config": (mutations_of(CONFIG_SEED) | json_values.map(lambda v: yaml.safe_dump(v, allow_unicode=True)), fuzz_config),
    "batch": (mutations_of(BATCH_SEED), fuzz_batch),
    "batch_lines": (st.lists(json_values | st.dictionaries(
        st.sampled_from(["world", "preset", "prompt", "seed", "name", "simulate", "export", "seeed"]), json_values,
        max_size=6), min_size=1, max_size=5), fuzz_batch_lines),
}


def run_target(name: str, value: Any) -> None:
    """Run one input; a GroveError is the expected way to refuse it, anything else propagates."""
    from grove_tui.errors import GroveError

    try:
        TARGETS[name][1](value)
    except GroveError:
        pass
