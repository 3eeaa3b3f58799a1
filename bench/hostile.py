"""Reproduce issue 17's table of hostile inputs: each case -> exit code and first line of the message.

    PYTHONPATH=. python bench/hostile.py [--only substring] [--skip-model]

Every case runs the real `grove` command line in a subprocess, in a fresh temporary folder with its
own GROVE_CONFIG_DIR / GROVE_DATA_DIR / GROVE_CACHE_DIR, and checks that the folder holds the same
files (same bytes) afterwards unless the case is meant to write. Cases that need the model (generate)
load the embedded one; --skip-model leaves them out. The output is a Markdown table (docs/HOSTILE.md
holds a run of it); the last line is key=value totals.
"""

from __future__ import annotations

import argparse
import hashlib
import json
import os
import re
import shutil
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

        folder = Path(tempfile.mkdtemp(prefix="grove-hostile-pristine-")) / "bundle"
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

CASES: list[Case] = [
    # world files
    Case("world file", "500-byte YAML alias bomb", lambda r: ["worlds", "check", str(write(r, "w.yaml", ALIAS_BOMB + "name: w\nzones: *i\n"))]),
    Case("world file", "nesting 10,000 deep", lambda r: ["worlds", "check", str(write(r, "w.yaml", "name: w\nzones: " + "[" * 10000 + "]" * 10000))]),
    Case("world file", "recursive alias", lambda r: ["worlds", "check", str(write(r, "w.yaml", "name: w\nzones: &x [*x]\n"))]),
    Case("world file", "5,000-digit integer", lambda r: ["worlds", "check", str(write(r, "w.yaml", room("[[0,0],[" + "9" * 5000 + ",0],[4,4]]")))]),
    Case("world file", "400-digit coordinate", lambda r: ["worlds", "check", str(write(r, "w.yaml", room("[[0,0],[" + "9" * 400 + ".5,0],[4,4]]")))]),
    Case("world file", "20 km x 20 km world (check)", lambda r: ["worlds", "check", str(write(r, "w.yaml", room("[[0,0],[20000,0],[20000,20000],[0,20000]]")))]),
    Case("world file", "20 km x 20 km world (generate)", lambda r: GENERATE[:2] + ["--world", str(write(r, "w.yaml", room("[[0,0],[20000,0],[20000,20000],[0,20000]]"))), "--preset", "normal", "--prompt", "ten people walk", "--out", str(r / "out")], model=True),
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
    Case("prompt", "500 people across the hospital evacuate", lambda r: GENERATE + ["--prompt", "500 people across the hospital evacuate", "--out", str(r / "out")], model=True),
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
        try:
            done = subprocess.run(GROVE + argv, stdout=stdout, stderr=subprocess.PIPE, text=True,
                                  env=_environment(root, case.env), timeout=600, cwd=root)
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
        return done.returncode, first, seconds, unchanged


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--only", default="", help="run the cases whose name contains this text")
    parser.add_argument("--skip-model", action="store_true", help="leave out the cases that load the model")
    args = parser.parse_args()
    cases = [c for c in CASES if args.only.lower() in c.name.lower() and not (args.skip_model and c.model)]
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
