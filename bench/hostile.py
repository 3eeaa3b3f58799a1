"""Reproduce the tables of hostile inputs (issues 17 and 35): each case -> exit code and first line of the message.

    PYTHONPATH=. python bench/hostile.py [--only substring] [--section name] [--skip-model]
    PYTHONPATH=. python bench/hostile.py --faults [--only command] [--skip-model]

Every case runs the real `grove` command line in a subprocess (the Gym cases: a short Python script, as
a user's training script would call the environment), in a fresh temporary folder with its own
GROVE_CONFIG_DIR / GROVE_DATA_DIR / GROVE_CACHE_DIR, and checks that the folder holds the same files
(same bytes) afterwards unless the case is meant to write. A full disk is a child process with
RLIMIT_FSIZE (writes past it fail with EFBIG, the code path of ENOSPC). Cases that need the model
(generate, batch) load the embedded one; --skip-model leaves them out. The output is a Markdown table
(docs/HOSTILE.md holds a run of it); the last line is key=value totals.

--faults kills each command (generate, batch, import hunav, simulate, metrics, the four exports) with
kill -9 at every write point in turn (tests/helpers/faults.py), and after each kill runs it again: the
table says whether the folders held the old state or the new one (never a torn file), and whether the
next run succeeded and left no staging entry.
"""

from __future__ import annotations

import argparse
import atexit
import hashlib
import json
import os
import re
import resource
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import zipfile
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import yaml

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO))
sys.path.insert(0, str(REPO / "tests"))  # `helpers.` as the suite imports it

GROVE = [sys.executable, "-c", "import sys; from grove_tui.cli import main; sys.argv[0] = 'grove'; main()"]


@dataclass
class Case:
    section: str
    name: str
    # Builds the inputs in `root` and returns the grove arguments (after `grove`).
    setup: Callable[[Path], list[str]]
    env: dict[str, str] = field(default_factory=dict)
    stdout_to: str | None = None  # a path for stdout (e.g. /dev/full); default: captured
    writes: bool = False  # the case is expected to write (only refusals must leave the folder as it was)
    model: bool = False  # loads the model
    python: str | None = None  # run this Python code (with the setup's list as sys.argv[1:]) instead of grove
    fsize: int | None = None  # a full disk: RLIMIT_FSIZE of the child, in bytes
    verify: Callable[[Path], str] | None = None  # after a case that writes: what it wrote, checked
    # A command prefix ("{root}" is the case's folder), e.g. unshare -m with a mount made for the child.
    wrap: list[str] | None = None


# ---- inputs ------------------------------------------------------------------------------------

ALIAS_BOMB = "a: &a [x,x,x,x,x,x,x,x,x]\n" + "".join(
    f"{chr(98 + i)}: &{chr(98 + i)} [" + ",".join(["*" + chr(97 + i)] * 9) + "]\n" for i in range(8))


def write(root: Path, name: str, text: str | bytes) -> Path:
    path = root / name
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_bytes(text if isinstance(text, bytes) else text.encode("utf-8"))
    return path


def room(boundary: str) -> str:
    return ("name: w\nzones:\n  - {name: z, type: r, boundary: " + boundary +
            ", doors: [{name: d, position: [2, 0], width: 1, leads_to: outside}]}\n")


def big_world(columns: int, rows: int, size: float = 2.0) -> str:
    from tests.world.test_world_limits import big_world as build

    return build(columns, rows, size)


def bundle(root: Path, simulated: bool = True) -> Path:
    """A copy of the hand-built hospital bundle (simulated once per run, then copied)."""
    target = root / "bundle"
    shutil.copytree(_pristine_bundle(simulated), target, symlinks=True)
    return target


_PRISTINE: dict[bool, Path] = {}


def _pristine_bundle(simulated: bool) -> Path:
    if simulated not in _PRISTINE:
        from tests.helpers.handmade import build_hospital_bundle

        root = tempfile.mkdtemp(prefix="grove-hostile-pristine-")
        atexit.register(shutil.rmtree, root, True)
        folder = Path(root) / "bundle"
        build_hospital_bundle(folder)
        if simulated:
            subprocess.run(GROVE + ["simulate", str(folder), "--seconds", "2"], check=True, capture_output=True,
                           env=_environment(folder.parent))
        _PRISTINE[simulated] = folder
    return _PRISTINE[simulated]


def edit_scenario(path: Path, change: Callable[[dict], None]) -> None:
    data = yaml.safe_load((path / "scenario.yaml").read_text())
    change(data)
    (path / "scenario.yaml").write_text(yaml.safe_dump(data, sort_keys=False))


def each_agent(key: str, value) -> Callable[[dict], None]:
    def change(data: dict) -> None:
        for agent in data["agents"]:
            agent[key] = value
    return change


def save_grid(path: Path, **overrides) -> None:
    with np.load(path / "grid.npz") as data:
        arrays = dict(data)
    arrays.update(overrides)
    np.savez_compressed(path / "grid.npz", **arrays)


def zip_bomb(path: Path, megabytes: int = 3300) -> None:
    header = np.lib.format.header_data_from_array_1_0(np.zeros((1, 1, 2), dtype=np.float32))
    side = int((megabytes * 2**20 / 8) ** 0.5)
    header["shape"] = (side, side, 2)
    path.parent.mkdir(parents=True, exist_ok=True)
    with zipfile.ZipFile(path, "w", compression=zipfile.ZIP_DEFLATED) as archive:
        with archive.open("vectors.npy", "w", force_zip64=True) as member:
            np.lib.format.write_array_header_1_0(member, header)
            chunk = bytes(1 << 24)
            for _ in range(megabytes // 16):
                member.write(chunk)


def with_field_bomb(root: Path) -> Path:
    """Agent 1 follows a velocity field whose file is a zip bomb (3 MB packed, 3.2 GB unpacked)."""
    b = bundle(root)
    zip_bomb(b / "fields" / "group_1.npz")
    write(b, "trees/agent_1.xml", '<root BTCPP_format="4" main_tree_to_execute="agent_1"><BehaviorTree ID="agent_1">'
                                  '<FollowVelocityField exit="main_entrance" field="group_1" x="30" y="1"/>'
                                  '</BehaviorTree></root>')
    edit_scenario(b, lambda data: data.__setitem__("fields", {"group_1": "fields/group_1.npz"}))
    return b


def truncated_model_dir(root: Path) -> None:
    from grove_tui.llm.registry import embedded_model_path

    data = embedded_model_path().read_bytes()
    write(root / "data" / "models", "cut.gguf", data[: len(data) // 2])


GENERATE = ["generate", "--no-ui", "--world", "hospital", "--preset", "emergency"]


# ---- issue 35 inputs ------------------------------------------------------------------------------


def hunav(root: Path, change: Callable[[dict], None] | None = None, text: str | bytes | None = None) -> str:
    """A small HuNavSim scenario (tests/helpers/hunav_files.py) with one change; the agents YAML's path."""
    from helpers.hunav_files import document, params, write_scenario

    values = params()
    if change is not None:
        change(values)
    return str(write_scenario(root / "scenario", text=text if text is not None else document(values)))


def agent(key: str, value) -> Callable[[dict], None]:
    def change(values: dict) -> None:
        node = values["agent1"]
        *parents, last = key.split(".")
        for part in parents:
            node = node[part]
        node[last] = value
    return change


def top(key: str, value) -> Callable[[dict], None]:
    return lambda values: values.__setitem__(key, value)


def one_group(count: int) -> Callable[[dict], None]:
    def change(values: dict) -> None:
        values["agents"] = [f"agent{i}" for i in range(1, count + 1)]
        for i in range(1, count + 1):
            values[f"agent{i}"] = dict(values["agent2"], id=i, group_id=7)
    return change


HUNAV_ALIAS_BOMB = ("hunav_loader:\n  ros__parameters:\n    yaml_base_name: agents_lab\n    map: lab\n"
                    "    a0: &a0 [agent1, agent1, agent1, agent1, agent1, agent1, agent1, agent1, agent1]\n"
                    + "".join(f"    a{i}: &a{i} [" + ", ".join([f"*a{i - 1}"] * 9) + "]\n" for i in range(1, 9))
                    + "    agents: *a8\n")


def import_into(root: Path, yaml_path: str) -> list[str]:
    return ["import", "hunav", yaml_path, "--out", str(root / "out")]


def fifo(path: Path) -> Path:
    path.parent.mkdir(parents=True, exist_ok=True)
    if path.exists() or path.is_symlink():
        path.unlink()
    os.mkfifo(path)
    return path


def relink(path: Path, target: str | Path) -> Path:
    if path.exists() or path.is_symlink():
        path.unlink()
    path.symlink_to(target)
    return path


def jobs(root: Path, *lines: str) -> str:
    return str(write(root, "jobs.jsonl", "\n".join(lines) + "\n"))


def job_line(**extra) -> str:
    return json.dumps({"world": "hospital", "preset": "normal", "prompt": "ten visitors walk to the cafeteria",
                       **extra})


def zigzag_world(points: int) -> str:
    edge = ", ".join(f"[{20 * i / points:.5f}, {0.01 * (i % 2)}]" for i in range(points))
    return ("name: w\nzones:\n  - {name: z, type: room, boundary: [" + edge + ", [20, 10], [0, 10]], "
            "doors: [{name: d, position: [0, 5], width: 1, leads_to: outside}]}\n")


def scenario_is_the_bundles(root: Path) -> str:
    text = (root / "out" / "scenario.yaml").read_text()
    world = (root / "out" / "world" / "scenario.yaml").is_file()
    return ("out/scenario.yaml is the bundle's (agents:), the world is out/world/scenario.yaml"
            if "agents:" in text and world else "LOST: scenario.yaml was replaced")


def torn_state_then_resume(root: Path) -> list[str]:
    """Two jobs ran; the record of the second was torn by a kill; a resumed batch adds a third job."""
    out = root / "out"
    out.mkdir()
    write(out, "batch-state.jsonl", '{"name": "a", "line": 1, "inputs": "x", "status": "ok"}\n{"name": "b", "inp')
    return ["batch", jobs(root, job_line(name="c", prompt="two visitors wait in the lobby")), "--out", str(out),
            "--resume"]


def resumed_records(root: Path) -> str:
    lines = (root / "out" / "batch-state.jsonl").read_bytes().splitlines()
    last = json.loads(lines[-1])
    return f"{len(lines)} lines; the new record stands on its own line: name={last['name']} status={last['status']}"


def agents_written(root: Path) -> str:
    scenario = yaml.safe_load((root / "out" / "scenario.yaml").read_text())
    return f"{len(scenario['agents'])} agents written"


# A mount namespace of the child's own (unshare -m, as root): an empty read-only file system at {root}/ro
# (a real EROFS, where /proc fails with ENOENT), or the bundle bound over itself (a mount point, which no
# rename can replace: EBUSY).
READ_ONLY_MOUNT = ["unshare", "-m", "sh", "-c", 'mount -t tmpfs -o ro grove-ro "$0" && exec "$@"', "{root}/ro"]
BUNDLE_MOUNT_POINT = ["unshare", "-m", "sh", "-c", 'mount --bind "$0" "$0" && exec "$@"', "{root}/bundle"]


def mount_point(root: Path, name: str) -> Path:
    (root / name).mkdir(exist_ok=True)
    return root / name


GYM = """
import sys
from grove_tui.errors import GroveError, print_error
import grove_tui.gym
from grove_tui.gym import SocialNavEnv
bundle, what = sys.argv[1], sys.argv[2]
try:
    if what.startswith("action:"):
        env = SocialNavEnv(bundle)
        env.reset(seed=0)
        env.step(eval(what[len("action:"):]))
    elif what.startswith("reset:"):
        env = SocialNavEnv(bundle)
        env.reset(options=eval(what[len("reset:"):]))
    elif what.startswith("bundles:"):
        SocialNavEnv(eval(what[len("bundles:"):]))
    else:
        SocialNavEnv(bundle, **eval(what))
except GroveError as exc:
    sys.exit(print_error(exc))
print("accepted")
"""


def gym(what: str) -> Case:
    return Case("35 gym", what, lambda r: [str(bundle(r, simulated=False)), what], python=GYM)

CASES: list[Case] = [
    # world files
    Case("world file", "500-byte YAML alias bomb", lambda r: ["worlds", "check", str(write(r, "w.yaml", ALIAS_BOMB + "name: w\nzones: *i\n"))]),
    Case("world file", "nesting 10,000 deep", lambda r: ["worlds", "check", str(write(r, "w.yaml", "name: w\nzones: " + "[" * 10000 + "]" * 10000))]),
    Case("world file", "recursive alias", lambda r: ["worlds", "check", str(write(r, "w.yaml", "name: w\nzones: &x [*x]\n"))]),
    Case("world file", "5,000-digit integer", lambda r: ["worlds", "check", str(write(r, "w.yaml", room("[[0,0],[" + "9" * 5000 + ",0],[4,4]]")))]),
    Case("world file", "400-digit coordinate", lambda r: ["worlds", "check", str(write(r, "w.yaml", room("[[0,0],[" + "9" * 400 + ".5,0],[4,4]]")))]),
    Case("world file", "18 km x 18 km world (check)", lambda r: ["worlds", "check", str(write(r, "w.yaml", room("[[-9000,-9000],[9000,-9000],[9000,9000],[-9000,9000]]")))]),
    Case("world file", "18 km x 18 km world (generate)", lambda r: GENERATE[:2] + ["--world", str(write(r, "w.yaml", room("[[-9000,-9000],[9000,-9000],[9000,9000],[-9000,9000]]"))), "--preset", "normal", "--prompt", "ten people walk", "--out", str(r / "out")], model=True),
    Case("world file", "valid world of 20,000 zones", lambda r: ["worlds", "check", str(write(r, "w.yaml", big_world(100, 200)))]),
    Case("world file", "world file is /dev/zero", lambda r: ["worlds", "check", "/dev/zero"]),
    # bundles
    Case("bundle", "missing scenario.yaml: metrics", lambda r: (os.remove(bundle(r) / "scenario.yaml"), ["metrics", str(r / "bundle")])[1]),
    Case("bundle", "missing scenario.yaml: export hunav", lambda r: (os.remove(bundle(r) / "scenario.yaml"), ["export", "hunav", str(r / "bundle"), "--out", str(r / "x")])[1]),
    Case("bundle", "broken scenario.yaml: picture", lambda r: (write(bundle(r), "scenario.yaml", "world: [\n"), ["picture", str(r / "bundle"), "--out", str(r / "p.png")])[1]),
    Case("bundle", "scenario.yaml alias bomb: simulate", lambda r: (write(bundle(r), "scenario.yaml", ALIAS_BOMB + "agents: *i\n"), ["simulate", str(r / "bundle")])[1]),
    Case("bundle", "truncated grid.npz: simulate", lambda r: (lambda b: (write(b, "grid.npz", (b / "grid.npz").read_bytes()[:100]), ["simulate", str(b)])[1])(bundle(r))),
    Case("bundle", "grid.npz resolution 0: simulate", lambda r: (lambda b: (save_grid(b, resolution=np.float64(0)), ["simulate", str(b)])[1])(bundle(r))),
    Case("bundle", "grid.npz NaN origin: export hunav", lambda r: (lambda b: (save_grid(b, origin=np.array([np.nan, 0.0])), ["export", "hunav", str(b), "--out", str(r / "x")])[1])(bundle(r))),
    Case("bundle", "grid.npz huge shape: simulate", lambda r: (lambda b: (save_grid(b, shape=np.array([10**9, 10**9])), ["simulate", str(b)])[1])(bundle(r))),
    Case("bundle", "3 MB zip bomb velocity field: export hunav", lambda r: ["export", "hunav", str(with_field_bomb(r)), "--out", str(r / "x")]),
    Case("bundle", "3 MB zip bomb velocity field: simulate", lambda r: ["simulate", str(with_field_bomb(r))]),
    Case("bundle", "seed: -1: simulate", lambda r: (lambda b: (edit_scenario(b, lambda d: d.__setitem__("seed", -1)), ["simulate", str(b)])[1])(bundle(r))),
    Case("bundle", "empty tree: simulate", lambda r: (lambda b: (write(b, "trees/agent_1.xml", ""), ["simulate", str(b)])[1])(bundle(r))),
    Case("bundle", "tree not XML: export hunav", lambda r: (lambda b: (write(b, "trees/agent_1.xml", "not xml at all"), ["export", "hunav", str(b), "--out", str(r / "x")])[1])(bundle(r))),
    Case("bundle", "tree symlink to /dev/zero: export hunav", lambda r: (lambda b: (os.remove(b / "trees/agent_1.xml"), os.symlink("/dev/zero", b / "trees/agent_1.xml"), ["export", "hunav", str(b), "--out", str(r / "x")])[2])(bundle(r))),
    Case("bundle", "tree path ../: export hunav", lambda r: (lambda b: (edit_scenario(b, each_agent("tree", "../../etc/passwd")), ["export", "hunav", str(b), "--out", str(r / "x")])[1])(bundle(r))),
    Case("bundle", "tree path absolute: simulate", lambda r: (lambda b: (edit_scenario(b, each_agent("tree", "/etc/passwd")), ["simulate", str(b)])[1])(bundle(r))),
    Case("bundle", "all agents have id 1: simulate", lambda r: (lambda b: (edit_scenario(b, each_agent("id", 1)), ["simulate", str(b)])[1])(bundle(r))),
    Case("bundle", "radius 1e6: simulate", lambda r: (lambda b: (edit_scenario(b, each_agent("radius", 1e6)), ["simulate", str(b)])[1])(bundle(r))),
    Case("bundle", "max_vel 1e308: simulate", lambda r: (lambda b: (edit_scenario(b, each_agent("max_vel", 1e308)), ["simulate", str(b)])[1])(bundle(r))),
    Case("bundle", "behavior: Berserk: export hunav", lambda r: (lambda b: (edit_scenario(b, each_agent("behavior", "Berserk")), ["export", "hunav", str(b), "--out", str(r / "x")])[1])(bundle(r))),
    Case("bundle", "simulate a folder that is not a bundle", lambda r: ["simulate", str((r / "empty").mkdir() or r / "empty")]),
    Case("trajectories", "NaN row: export trajectories", lambda r: (lambda b: (open(b / "trajectories.csv", "a").write("9999,1.0,1,nan,2,0,0,0,-1\n"), ["export", "trajectories", str(b), "--out", str(r / "x")])[1])(bundle(r))),
    # trees
    Case("tree input", "bt validate /dev/zero", lambda r: ["bt", "validate", "/dev/zero"]),
    Case("tree input", "2,400 SubTrees calling unknown IDs", lambda r: ["bt", "validate", str(write(r, "t.xml", (
        '<root BTCPP_format="4" main_tree_to_execute="M"><BehaviorTree ID="M"><Sequence>'
        + "".join(f'<SubTree ID="missing_tree_{i}"/>' for i in range(2400)) + "</Sequence></BehaviorTree></root>")))]),
    Case("tree input", "a chain of 2,400 SubTrees", lambda r: ["bt", "validate", str(write(r, "t.xml", (
        '<root BTCPP_format="4" main_tree_to_execute="T0">'
        + "".join(f'<BehaviorTree ID="T{i}"><SubTree ID="T{i + 1}"/></BehaviorTree>' for i in range(2400))
        + '<BehaviorTree ID="T2400"><Wait/></BehaviorTree></root>')))]),
    # config and environment
    Case("config", "GROVE_CONFIG_FILE=/etc/passwd", lambda r: ["models", "list"], env={"GROVE_CONFIG_FILE": "/etc/passwd"}),
    Case("config", "config with a !!python tag", lambda r: ["models", "list"], env={"GROVE_CONFIG_FILE": "{root}/c.yaml"}),
    Case("config", "GROVE_LLM_THREADS=abc", lambda r: ["models", "list"], env={"GROVE_LLM_THREADS": "abc"}),
    Case("models", "truncated GGUF in the models folder: models list", lambda r: (truncated_model_dir(r), ["models", "list"])[1]),
    # batch
    Case("batch", "only bad jobs (seed abc, prompt 123, simulate abc, seeed)", lambda r: ["batch", str(write(r, "jobs.jsonl", "\n".join(json.dumps(j) for j in (
        {"world": "hospital", "preset": "normal", "prompt": "ten people", "seed": "abc"},
        {"world": "hospital", "preset": "normal", "prompt": 123},
        {"world": "hospital", "preset": "normal", "prompt": "ten people", "simulate": "abc"},
        {"world": "hospital", "preset": "normal", "prompt": "ten people", "seeed": 1})))), "--out", str(r / "out")]),
    Case("batch", "two jobs with the same name", lambda r: ["batch", str(write(r, "jobs.jsonl", "\n".join(json.dumps(j) for j in (
        {"world": "hospital", "preset": "normal", "prompt": "ten people walk", "name": "same"},
        {"world": "hospital", "preset": "normal", "prompt": "two people wait", "name": "same"})))), "--out", str(r / "out")],
         writes=True, model=True),  # the good first job runs; the duplicate is refused
    Case("batch", "non-UTF-8 job file", lambda r: ["batch", str(write(r, "jobs.jsonl", b"\xff\xfe{}\n")), "--out", str(r / "out")]),
    # prompts
    Case("prompt", "zero people evacuate the cafeteria", lambda r: GENERATE + ["--prompt", "zero people evacuate the cafeteria", "--out", str(r / "out")], model=True),
    Case("prompt", "-5 people", lambda r: GENERATE + ["--prompt", "-5 people evacuate the cafeteria", "--out", str(r / "out")], model=True),
    Case("prompt", "a billion people", lambda r: GENERATE + ["--prompt", "a billion people evacuate the cafeteria", "--out", str(r / "out")], model=True),
    Case("prompt", "501 people evacuate the hospital (limit 500)", lambda r: GENERATE + ["--prompt", "501 people evacuate the hospital", "--out", str(r / "out")], model=True),
    Case("prompt", "500 people across the hospital evacuate", lambda r: GENERATE + ["--prompt", "500 people across the hospital evacuate", "--out", str(r / "out")], model=True, writes=True, verify=lambda r: agents_written(r)),
    Case("prompt", "emoji only", lambda r: GENERATE + ["--prompt", "🔥🔥🔥", "--out", str(r / "out")], model=True),
    # arguments
    Case("arguments", "--seed -1", lambda r: GENERATE + ["--prompt", "ten people evacuate", "--seed", "-1", "--out", str(r / "out")]),
    Case("arguments", "--simulate nan", lambda r: GENERATE + ["--prompt", "ten people evacuate", "--simulate", "nan", "--out", str(r / "out")]),
    Case("arguments", "--simulate inf", lambda r: GENERATE + ["--prompt", "ten people evacuate", "--simulate", "inf", "--out", str(r / "out")]),
    Case("arguments", "simulate --seconds inf", lambda r: ["simulate", str(bundle(r)), "--seconds", "inf"]),
    Case("arguments", "--out on a read-only file system", lambda r: GENERATE + ["--prompt", "ten people evacuate", "--out", "/proc/grove-out"]),
    Case("arguments", "stdout is /dev/full", lambda r: ["worlds", "list"], stdout_to="/dev/full"),
    # data loss (fixed earlier on main; kept in the table)
    Case("data loss", "--out is a user's folder", lambda r: (write(r, "mine/notes.txt", "keep me"), GENERATE + ["--prompt", "ten people evacuate", "--out", str(r / "mine")])[1]),
    Case("data loss", "--out . (the working folder)", lambda r: (write(r, "notes.txt", "keep me"), GENERATE + ["--prompt", "ten people evacuate", "--out", "."])[1]),
    Case("data loss", "--out is a device node", lambda r: GENERATE + ["--prompt", "ten people evacuate", "--out", "/dev/full"]),
    Case("data loss", "export --base-name ../../x", lambda r: ["export", "hunav", str(bundle(r)), "--out", str(r / "x"), "--base-name", "../../x"]),
    # ---- issue 35 ----
    # data loss
    Case("35 data loss", "metrics: metrics.json links to a user's file", lambda r: (write(r, "thesis.tex", "keep me"), relink(bundle(r) / "metrics.json", r / "thesis.tex"), ["metrics", str(r / "bundle")])[2]),
    Case("35 data loss", "export trajectories into a user's folder", lambda r: (write(r, "mine/trajectories.csv", "my own data"), ["export", "trajectories", str(bundle(r)), "--out", str(r / "mine")])[1]),
    Case("35 data loss", "export foxglove over a file that is not MCAP", lambda r: (write(r, "mine.mcap", "a recording"), ["export", "foxglove", str(bundle(r)), "--out", str(r / "mine.mcap")])[1]),
    Case("35 data loss", "export foxglove beside a user's layout", lambda r: (write(r, "mine.layout.json", '{"my": "layout"}'), ["export", "foxglove", str(bundle(r)), "--out", str(r / "mine.mcap")])[1]),
    Case("35 data loss", "import hunav with map: scenario", lambda r: import_into(r, hunav(r, top("map", "scenario"))), writes=True, verify=scenario_is_the_bundles),
    # import hunav
    Case("35 import hunav", "init_pose as a list", lambda r: import_into(r, hunav(r, agent("init_pose", [0.5, 4.0])))),
    Case("35 import hunav", "behavior: Scared as a string", lambda r: import_into(r, hunav(r, agent("behavior", "Scared")))),
    Case("35 import hunav", "20,000 nested brackets", lambda r: import_into(r, hunav(r, text="hunav_loader: " + "[" * 20000 + "]" * 20000 + "\n"))),
    Case("35 import hunav", ".inf pose, unknown map", lambda r: import_into(r, hunav(r, agent("init_pose.x", float("inf"))))),
    Case("35 import hunav", ".nan goal, unknown map", lambda r: import_into(r, hunav(r, lambda v: v["global_goals"].__setitem__(2, {"x": float("nan"), "y": 1.5})))),
    Case("35 import hunav", "5,000-character map", lambda r: import_into(r, hunav(r, top("map", "m" * 5000)))),
    Case("35 import hunav", "file not UTF-8", lambda r: import_into(r, hunav(r, text=b"hunav_loader:\n  ros__parameters:\n    map: caf\xe9\n"))),
    Case("35 import hunav", "link to /dev/zero", lambda r: import_into(r, str(relink(r / "zero.yaml", "/dev/zero")))),
    Case("35 import hunav", "alias bomb in the agents list (hang)", lambda r: import_into(r, hunav(r, text=HUNAV_ALIAS_BOMB))),
    Case("35 import hunav", "named pipe (hang)", lambda r: import_into(r, str(fifo(r / "pipe.yaml")))),
    Case("35 import hunav", "NaN start pose", lambda r: import_into(r, hunav(r, agent("init_pose.y", float("nan"))))),
    Case("35 import hunav", "max_vel inf", lambda r: import_into(r, hunav(r, agent("max_vel", float("inf"))))),
    Case("35 import hunav", "max_vel -3", lambda r: import_into(r, hunav(r, agent("max_vel", -3.0)))),
    Case("35 import hunav", "behavior Berserk", lambda r: import_into(r, hunav(r, agent("behavior.type", "Berserk")))),
    Case("35 import hunav", "a group of 10^30", lambda r: import_into(r, hunav(r, agent("group_id", 10**30)))),
    Case("35 import hunav", "501 agents in one group", lambda r: import_into(r, hunav(r, one_group(501)))),
    Case("35 import hunav", "50,000 agents in one group", lambda r: import_into(r, hunav(r, one_group(50_000)))),
    Case("35 import hunav", "1,000,000 names in the agents list", lambda r: import_into(r, hunav(r, text="hunav_loader:\n  ros__parameters:\n    map: lab\n    agents: [" + ", ".join(["x"] * 1_000_000) + "]\n"))),
    Case("35 import hunav", "imported bundle simulated from another folder", lambda r: (subprocess.run(GROVE + import_into(r, hunav(r)), env=_environment(r), capture_output=True, cwd=r), write(r, "elsewhere/world/lab.yaml", "name: decoy\nzones: []\n"), ["simulate", str(r / "out"), "--seconds", "1"])[2], writes=True),
    # batch
    Case("35 batch", "a prompt with a lone surrogate", lambda r: ["batch", jobs(r, job_line(prompt="visitors \ud800 walk")), "--out", str(r / "out")]),
    Case("35 batch", "a job named dataset.sqlite", lambda r: ["batch", jobs(r, job_line(name="dataset.sqlite")), "--out", str(r / "out")]),
    Case("35 batch", "a 5,000-digit variations", lambda r: ["batch", jobs(r, '{"world": "hospital", "preset": "normal", "prompt": "x", "variations": ' + "9" * 5000 + "}"), "--out", str(r / "out")]),
    Case("35 batch", "a torn last record, then --resume", torn_state_then_resume, writes=True, model=True, verify=resumed_records),
    Case("35 batch", "stale staging and .dataset.sqlite.tmp, then --resume", lambda r: (write(r, "out/.dataset.sqlite.tmp", "half"), (r / "out" / ".a.0a7c9cdf-999999.abcdefgh.staging").mkdir(), ["batch", jobs(r, job_line(name="a", prompt="two visitors wait in the lobby")), "--out", str(r / "out"), "--resume"])[2], writes=True, model=True, verify=lambda r: "left: " + (", ".join(sorted(p.name for p in (r / "out").iterdir() if p.name.startswith("."))) or "nothing")),
    # worlds
    Case("35 world file", "one 200,000-point boundary (batch)", lambda r: ["batch", jobs(r, json.dumps({"world": str(write(r, "w.yaml", zigzag_world(200_000))), "preset": "normal", "prompt": "two people walk", "name": "zigzag"})), "--out", str(r / "out")], model=True),
    Case("35 world file", "one 200,000-point boundary (check)", lambda r: ["worlds", "check", str(write(r, "w.yaml", zigzag_world(200_000)))]),
    Case("35 world file", "one 200,000-point boundary (generate)", lambda r: ["generate", "--no-ui", "--world", str(write(r, "w.yaml", zigzag_world(200_000))), "--preset", "normal", "--prompt", "two people walk", "--out", str(r / "out")], model=True),
    Case("35 world file", "a world near 99,999 m (check)", lambda r: ["worlds", "check", str(write(r, "w.yaml", room("[[99990,0],[99999,0],[99999,9],[99990,9]]")))]),
    Case("35 world file", "link to a private file (check)", lambda r: ["worlds", "check", str(relink(r / "w.yaml", write(r, "shadow", "root:$6$SECRET:19000:0:99999:7:::\ndaemon:*:19000:0:99999:7:::\n")))]),
    # exports and metrics
    Case("35 exports", "export trajectories onto a device node", lambda r: ["export", "trajectories", str(bundle(r)), "--out", "/dev/full"]),
    Case("35 exports", "export trajectories onto a read-only file system", lambda r: ["export", "trajectories", str(bundle(r)), "--out", "/proc/grove-out"]),
    Case("35 exports", "export trajectories onto a real read-only mount (EROFS)", lambda r: ["export", "trajectories", str(bundle(r)), "--out", str(mount_point(r, "ro") / "traj")], wrap=READ_ONLY_MOUNT),
    Case("35 exports", "export foxglove onto a real read-only mount (EROFS)", lambda r: ["export", "foxglove", str(bundle(r)), "--out", str(mount_point(r, "ro") / "run.mcap")], wrap=READ_ONLY_MOUNT),
    Case("35 exports", "simulate a bundle that is a mount point (EBUSY)", lambda r: ["simulate", str(bundle(r)), "--seconds", "1"], wrap=BUNDLE_MOUNT_POINT),
    Case("35 exports", "export trajectories on a full disk", lambda r: ["export", "trajectories", str(bundle(r)), "--out", str(r / "new" / "traj")], fsize=40_000),
    Case("35 exports", "export foxglove on a full disk", lambda r: ["export", "foxglove", str(bundle(r)), "--out", str(r / "new" / "run.mcap")], fsize=40_000),
    Case("35 metrics", "trajectories.csv links to /dev/zero", lambda r: (relink(bundle(r) / "trajectories.csv", "/dev/zero"), ["metrics", str(r / "bundle")])[1]),
    Case("35 metrics", "events.jsonl links to /dev/zero", lambda r: (relink(bundle(r) / "events.jsonl", "/dev/zero"), ["metrics", str(r / "bundle")])[1]),
    Case("35 metrics", "trajectories.csv is a named pipe (hang)", lambda r: (fifo(bundle(r) / "trajectories.csv"), ["metrics", str(r / "bundle")])[1]),
    Case("35 metrics", "events.jsonl is a named pipe (hang)", lambda r: (fifo(bundle(r) / "events.jsonl"), ["metrics", str(r / "bundle")])[1]),
    # odd numbers and letters in prompts (the counts written, through generation)
    Case("35 prompt", "2.5 people (was 112)", lambda r: GENERATE[:4] + ["--preset", "normal", "--prompt", "2.5 people walk to the cafeteria", "--out", str(r / "out")], model=True, writes=True, verify=agents_written),
    Case("35 prompt", "an emoji family (was 60)", lambda r: GENERATE[:4] + ["--preset", "normal", "--prompt", "\U0001F468\u200d\U0001F469\u200d\U0001F467\u200d\U0001F466 a family walks to the cafeteria", "--out", str(r / "out")], model=True, writes=True, verify=agents_written),
    Case("35 prompt", "full-width letters (was 'only symbols or emoji')", lambda r: GENERATE[:4] + ["--preset", "normal", "--prompt", "\uff54\uff57\uff4f \uff4e\uff55\uff52\uff53\uff45\uff53 \uff57\uff41\uff4c\uff4b \uff54\uff4f \uff54\uff48\uff45 \uff43\uff41\uff46\uff45\uff54\uff45\uff52\uff49\uff41", "--out", str(r / "out")], model=True, writes=True, verify=agents_written),
    Case("35 prompt", "a full-width minus (-5)", lambda r: GENERATE[:4] + ["--preset", "normal", "--prompt", "\uff0d\uff15 people walk to the cafeteria", "--out", str(r / "out")], model=True),
    # the Gym environment
    gym("action:'fast'"), gym("action:{'v': 1}"), gym("action:complex(1, 2)"), gym("action:10**400"),
    gym("{'control_period': float('inf')}"), gym("{'control_period': '0.2'}"), gym("reset:{'scenario': float('nan')}"),
    gym("bundles:5"), gym("{'observation': {'pedestrians': 10**9}}"), gym("{'observation': {'patch_cells': 10**6}}"),
    gym("{'time_limit': 1e300}"), gym("{'time_limit': 1e6}"), gym("{'speed': 2.0}"), gym("{'sim_dt': 1e-300}"),
]


def _environment(root: Path, extra: dict[str, str] | None = None) -> dict[str, str]:
    env = {key: value for key, value in os.environ.items() if not key.startswith("GROVE_")}
    env.update(GROVE_CONFIG_DIR=str(root / "config"), GROVE_DATA_DIR=str(root / "data"),
               GROVE_CACHE_DIR=str(root / "cache"), PYTHONPATH=str(REPO), COLUMNS="200")
    for key, value in (extra or {}).items():
        env[key] = value.replace("{root}", str(root))
    return env


def snapshot(root: Path) -> dict[str, str]:
    """Every entry under root but the cache (the node index is built there on first use)."""
    state = {}
    for path in sorted(root.rglob("*")):
        rel = str(path.relative_to(root))
        if rel == "cache" or rel.startswith("cache/"):
            continue
        if path.is_symlink():
            state[rel] = "-> " + os.readlink(path)
        elif path.is_file():
            digest = hashlib.sha256()
            with path.open("rb") as handle:
                for block in iter(lambda: handle.read(1 << 20), b""):
                    digest.update(block)
            state[rel] = digest.hexdigest()
        elif path.is_dir():
            state[rel] = "dir"
        else:
            state[rel] = "special"
    return state


def _full_disk(limit: int) -> Callable[[], None]:
    def limit_writes() -> None:
        signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
        resource.setrlimit(resource.RLIMIT_FSIZE, (limit, limit))
    return limit_writes


def run(case: Case) -> tuple[int, str, float, bool]:
    with tempfile.TemporaryDirectory(prefix="grove-hostile-") as folder:
        root = Path(folder)
        for sub in ("config", "data", "cache"):
            (root / sub).mkdir()
        write(root, "c.yaml", "ui: !!python/object/apply:os.system ['true']\n")
        argv = case.setup(root)
        before = snapshot(root)
        started = time.perf_counter()
        stdout = open(case.stdout_to, "w") if case.stdout_to else subprocess.PIPE  # noqa: SIM115
        command = [sys.executable, "-c", case.python] if case.python else GROVE
        if case.wrap:
            command = [part.replace("{root}", str(root)) for part in case.wrap] + command
        cwd = root / "elsewhere" if (root / "elsewhere").is_dir() else root
        try:
            done = subprocess.run(command + argv, stdout=stdout, stderr=subprocess.PIPE, text=True,
                                  env=_environment(root, case.env), timeout=600, cwd=cwd,
                                  preexec_fn=_full_disk(case.fsize) if case.fsize else None)
        finally:
            if case.stdout_to:
                stdout.close()
        seconds = time.perf_counter() - started
        lines = [line for line in (done.stderr or "").splitlines() if line.strip()]
        output = [line.strip() for line in (done.stdout or "").splitlines() if line.strip()]
        errors = [line for line in lines if line.startswith("error:")]
        if errors:
            first = errors[0]
        elif any("Traceback" in line for line in lines):
            first = "TRACEBACK: " + lines[-1]
        else:
            shown = lines or output
            first = shown[0] if shown else ""
            # `worlds check` and `bt validate` print a count, then one problem per line: show the first.
            if first.endswith(":") and len(shown) > 1:
                first = f"{first} {shown[1].strip()}"
            damaged = re.search(r"truncated: its tensors[^)]*", " ".join(" ".join(output).replace("│", " ").split()))
            if damaged:  # models list: the reason given in the damaged model's row
                first = "cut.gguf: " + damaged.group(0)
        unchanged = snapshot(root) == before
        if case.verify is not None and done.returncode == 0:
            first = f"{first} -> {case.verify(root)}" if first else case.verify(root)
        return done.returncode, first.replace(str(root), "TMP"), seconds, unchanged


def faults(only: str, skip_model: bool, limit: int | None) -> None:
    """kill -9 at every write point of each command, then run it again (tests/helpers/faults.py)."""
    from helpers.faults import sweep
    from helpers.hunav_files import write_scenario

    with tempfile.TemporaryDirectory(prefix="grove-faults-") as folder:
        root = Path(folder)
        os.environ.update({key: value for key, value in _environment(root).items()
                           if key.startswith("GROVE_")})
        simulated = bundle(root)
        yaml_path = write_scenario(root / "scenario")
        out = root / "out"
        # The batch's own writes: its bundles, its records and its index (a job's simulation and exports
        # are the simulate and export commands' writes, swept below on their own).
        batch_jobs = jobs(root, job_line(name="visitors", prompt="two visitors walk to the cafeteria"),
                          job_line(name="waiting", prompt="three patients wait in the lobby"))
        commands = {
            "generate": (["generate", "--no-ui", "--world", "hospital", "--preset", "normal", "--prompt",
                          "two visitors walk to the cafeteria", "--seed", "1", "--out", out / "generated"],
                         [out / "generated"], True),
            "batch": (["batch", batch_jobs, "--out", out / "batch"], [out / "batch"], True),
            "import hunav": (["import", "hunav", yaml_path, "--out", out / "imported"], [out / "imported"], False),
            "simulate": (["simulate", simulated, "--seconds", "1"], [simulated], False),
            "metrics": (["metrics", simulated], [simulated], False),
            "export trajectories": (["export", "trajectories", simulated, "--out", out / "traj"], [out / "traj"], False),
            "export hunav": (["export", "hunav", simulated, "--out", out / "hunav"], [out / "hunav"], False),
            "export rosbag": (["export", "rosbag", simulated, "--out", out / "bag"], [out / "bag"], False),
            "export foxglove": (["export", "foxglove", simulated, "--out", out / "run.mcap"], [out], False),
        }
        print("| command | write points | killed | old or new state | next run ok, no staging left |")
        print("|---|---|---|---|---|")
        totals = {"points": 0, "torn": 0, "unclean": 0}
        for name, (args, watched, needs_model) in commands.items():
            if only.lower() not in name or (skip_model and needs_model):
                continue
            started = time.perf_counter()
            results = sweep(args, watched, limit=limit)
            torn = [r for r in results if r["state"] != "old or new"]
            unclean = [r for r in results if not r["next_run_clean"]]
            totals["points"] += len(results)
            totals["torn"] += len(torn)
            totals["unclean"] += len(unclean)
            labels = sorted({r["label"].split(":")[0] + ":" + r["label"].split(":")[-1] for r in results})
            print(f"| {name} | {len(results)} ({', '.join(labels)}) | {sum(r['killed'] for r in results)} | "
                  f"{len(results) - len(torn)}/{len(results)} | {len(results) - len(unclean)}/{len(results)} "
                  f"({time.perf_counter() - started:.0f} s) |", flush=True)
            for bad in torn + unclean:
                print(f"|   | {bad['label']} #{bad['n']} | | {bad['state']} | {bad['next_run_clean']} |", flush=True)
        print(f"\nfault_points={totals['points']} torn={totals['torn']} unclean_next_runs={totals['unclean']}")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--only", default="", help="run the cases (or --faults commands) whose name contains this text")
    parser.add_argument("--section", default="", help="run the cases whose section contains this text")
    parser.add_argument("--skip-model", action="store_true", help="leave out the cases that load the model")
    parser.add_argument("--faults", action="store_true", help="kill -9 at every write point instead")
    parser.add_argument("--limit", type=int, default=None, help="--faults: at most this many points per command")
    args = parser.parse_args()
    if args.faults:
        faults(args.only, args.skip_model, args.limit)
        return
    cases = [c for c in CASES if args.only.lower() in c.name.lower() and args.section.lower() in c.section.lower()
             and not (args.skip_model and c.model)]
    print("| section | case | exit | s | files unchanged | first line of the message |")
    print("|---|---|---|---|---|---|")
    tracebacks = bad_input = 0
    for case in cases:
        code, first, seconds, unchanged = run(case)
        tracebacks += first.startswith("TRACEBACK")
        bad_input += code == 2
        text = first.replace("|", "\\|")
        if len(text) > 220:
            text = text[:217] + "..."
        print(f"| {case.section} | {case.name} | {code} | {seconds:.1f} | {'yes' if unchanged else 'wrote (expected)' if case.writes else 'NO'} | {text} |",
              flush=True)
    print(f"\ncases={len(cases)} exit_2={bad_input} tracebacks={tracebacks}")


if __name__ == "__main__":
    main()
