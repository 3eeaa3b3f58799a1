"""Hypothesis strategies and targets for fuzzing every parser GROVE exposes to user files, and the Gym
environment's config and actions.

Shared by tests/test_fuzz.py (a bounded run in CI) and bench/fuzz.py (minutes per parser, by hand).
A target takes one generated input and exercises the parser the way the product does; the only
acceptable failure is a GroveError (the message a user sees), or for the Gym targets gymnasium's own
error class where gymnasium has one (EXPECTED). Anything else is a bug.

Inputs are mutations of valid seeds (so they get past the first checks and reach deep code) plus
structured values of the wrong shapes (so type checks are exercised): the tokens inserted are the
ones the hostile-input review used (aliases, anchors, deep brackets, huge and non-finite numbers,
Python tags, entities, paths that escape, NUL bytes).
"""

from __future__ import annotations

import atexit
import json
import os
import shutil
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

def _hunav_text_seed() -> str:
    from helpers.hunav_files import document, params

    return document(params())


HUNAV_TEXT_SEED = _hunav_text_seed()

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
    from grove_tui.bt.format.xml import check_tree_text, parse_tree_text

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


# -- `grove import hunav` ------------------------------------------------------------------------------


def _hunav_variants() -> st.SearchStrategy[Any]:
    """The valid parameters with one value (top level, an agent's, a goal's) replaced by anything."""
    from helpers.hunav_files import params

    top = st.sampled_from(sorted(params()))
    agent_key = st.sampled_from(sorted(params()["agent1"]) + ["init_pose.x", "init_pose.y", "behavior.type"])

    def replace_top(key_value):
        key, value = key_value
        data = params()
        data[key] = value
        return data

    def replace_agent(key_value):
        key, value = key_value
        data = params()
        node = data["agent1"]
        *parents, last = key.split(".")
        for part in parents:
            node = node[part]
        node[last] = value
        return data

    hostile = st.sampled_from([float("nan"), float("inf"), -float("inf"), 1e300, -3.0, 10**30, 0, -1, 5e4,
                               "Scared", "Berserk", [0.5, 4.0], {"x": float("nan")}, "m" * 300, "../x", None])
    value = hostile | json_values
    # Agent values are what the hostile review broke the import with: weight them.
    return (st.tuples(agent_key, value).map(replace_agent) | st.tuples(agent_key, hostile).map(replace_agent)
            | st.tuples(top, value).map(replace_top))


def fuzz_hunav_import(data: Any) -> None:
    """Import a HuNavSim scenario (parameters, or raw text); what imports must load as simulate loads it."""
    from helpers.hunav_files import document, write_scenario

    from grove_tui.exports.hunav_import import import_hunav
    from grove_tui.scenario.bundle import load_bundle

    with tempfile.TemporaryDirectory(prefix="grove-fuzz-") as folder:
        if isinstance(data, dict):
            try:
                text = document(data)
            except (ValueError, TypeError, OverflowError, RecursionError):  # YAML cannot write the value
                return
        else:
            text = data
        path = write_scenario(Path(folder) / "scenario", text=text)
        bundle = import_hunav(path, Path(folder) / "bundle")
        load_bundle(bundle)


# -- the Gym environment ---------------------------------------------------------------------------------

_GYM: dict[str, Any] = {}


def _gym_bundle() -> Path:
    """One hand-built bundle with a robot, made once per process."""
    if "bundle" not in _GYM:
        from helpers.handmade import build_hospital_bundle

        folder = tempfile.mkdtemp(prefix="grove-fuzz-gym-")
        atexit.register(shutil.rmtree, folder, True)  # one per process, gone when it ends
        _GYM["bundle"] = build_hospital_bundle(Path(folder) / "bundle")
    return _GYM["bundle"]


_GYM_NUMBERS = (st.floats(allow_nan=True, allow_infinity=True) | st.integers(min_value=-(10**400), max_value=10**400)
                | st.sampled_from([0, 1, 2, 0.05, 0.2, 1e-300, 1e300, 10**9, "0.2", True, None, complex(1, 1), [], {}]))
_GYM_ARGS = ("control_period", "sim_dt", "time_limit", "max_angular_speed", "goal_tolerance", "start_jitter",
             "metrics_every", "kinematics", "pedestrian_model", "render_mode", "seeds")
_SUB_FIELDS = {"observation": ("pedestrians", "sensor_range", "patch_cells", "patch_resolution"),
               "reward": ("success", "collision", "progress", "intimate", "personal", "timeout", "intimate_distance",
                          "personal_distance")}


def _gym_configs() -> st.SearchStrategy[dict[str, Any]]:
    value = _GYM_NUMBERS | json_values | st.sampled_from(["unicycle", "holonomic", "grove", "lightsfm"])
    sub = {name: st.dictionaries(st.sampled_from(keys) | st.text(max_size=4), _GYM_NUMBERS | json_values, max_size=3)
           | json_values for name, keys in _SUB_FIELDS.items()}
    return st.fixed_dictionaries({}, optional={**{name: value for name in _GYM_ARGS}, **sub,
                                               "unknown_keyword": value, "bundles": json_values,
                                               "reset_options": json_values | st.fixed_dictionaries(
                                                   {"scenario": _GYM_NUMBERS})})


def fuzz_gym_config(config: dict[str, Any]) -> None:
    """Make the env with fuzzed arguments; when it is made, reset (fuzzed options) and take two steps."""
    from grove_tui.gym import SocialNavEnv

    kwargs = dict(config)
    bundles = kwargs.pop("bundles", None)
    options = kwargs.pop("reset_options", None)
    if "seeds" in kwargs and bundles is None:
        kwargs.pop("seeds")  # seeds with bundles is refused; without bundles it would generate with the model
    env = SocialNavEnv(bundles if bundles is not None else _gym_bundle(), **kwargs)
    try:
        env.reset(seed=0, options=options)
        for _ in range(2):
            _obs, _reward, terminated, truncated, _info = env.step(env.action_space.sample())
            if terminated or truncated:
                break
    finally:
        env.close()


def _gym_actions() -> st.SearchStrategy[Any]:
    numbers = _GYM_NUMBERS | st.floats(min_value=-2, max_value=2)
    return (st.lists(numbers, max_size=4) | st.tuples(numbers, numbers) | json_values | numbers
            | st.builds(lambda a, b: __import__("numpy").array([a, b]), st.floats(), st.floats()))


def fuzz_gym_action(action: Any) -> None:
    """One env, stepped with a fuzzed action (reset when its episode ended); reset with fuzzed options too."""
    from grove_tui.gym import SocialNavEnv

    if "env" not in _GYM:
        _GYM["env"] = SocialNavEnv(_gym_bundle())
        _GYM["env"].reset(seed=0)
    env = _GYM["env"]
    if env.outcome:
        env.reset()
    if isinstance(action, dict) and action:
        env.reset(seed=None, options=action)  # options of any shape
        return
    env.step(action)


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
    "hunav_import": (_hunav_variants(), fuzz_hunav_import),
    "hunav_import_text": (mutations_of(HUNAV_TEXT_SEED), fuzz_hunav_import),
}
try:
    import gymnasium  # noqa: F401  (the Gym targets need the optional extra)
except ImportError:
    pass
else:
    TARGETS["gym_config"] = (_gym_configs(), fuzz_gym_config)
    TARGETS["gym_action"] = (_gym_actions(), fuzz_gym_action)


def expected_errors() -> tuple[type[BaseException], ...]:
    """What a target may raise: GroveError, and gymnasium's own errors (a bad reset seed) when installed."""
    from grove_tui.errors import GroveError

    try:
        import gymnasium.error
    except ImportError:
        return (GroveError,)
    return (GroveError, gymnasium.error.Error)


def run_target(name: str, value: Any) -> None:
    """Run one input; a GroveError is the expected way to refuse it, anything else propagates."""
    try:
        TARGETS[name][1](value)
    except expected_errors():
        pass
