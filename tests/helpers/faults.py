"""kill -9 at a chosen write point: run `grove ...` in a child process that SIGKILLs itself there.

grove_tui.files calls `write_point(label)` at every step a crash could interrupt (a staging folder made and
filled, a file written and renamed, a record appended); the child installs `files.WRITE_POINT_HOOK` to
kill itself at the N-th label matching a pattern, so no handler, `finally` or atexit runs: exactly what
kill -9 or a power cut leaves. `write_points` lists the labels a command passes, in order, to sweep them.

Shared by tests/test_faults.py (a sample in CI) and bench/hostile.py --faults (every point).
"""

from __future__ import annotations

import fnmatch
import hashlib
import json
import os
import re
import signal
import subprocess
import sys
import tempfile
from collections.abc import Sequence
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
# Staging entries GROVE makes beside a target (grove_tui/files.py), of any version.
STAGING = re.compile(r"^\..+\.(staging|tmp|old)$")

_CHILD = """
import fnmatch, json, os, signal, sys
import grove_tui.files as files
pattern, occurrence, log = sys.argv[1], int(sys.argv[2]), sys.argv[3]
seen = 0
def hook(label):
    global seen
    if log:
        with open(log, "a") as out:
            out.write(label + "\\n")
    if pattern and fnmatch.fnmatch(label, pattern):
        seen += 1
        if seen == occurrence:
            os.kill(os.getpid(), signal.SIGKILL)
files.WRITE_POINT_HOOK = hook
{body}
"""
_CLI = """
from grove_tui.cli import main
sys.argv = ["grove"] + sys.argv[4:]
main()
"""


def _environment() -> dict[str, str]:
    return dict(os.environ, PYTHONPATH=os.pathsep.join(p for p in (str(REPO), os.environ.get("PYTHONPATH")) if p))


def run_grove(args: Sequence[str | os.PathLike[str]], *, kill_at: str = "", occurrence: int = 1,
              log: Path | None = None, cwd: Path | None = None, body: str = _CLI,
              timeout: float = 600) -> subprocess.CompletedProcess:
    """`grove args` in a child; killed (-9) at the `occurrence`-th write point matching `kill_at`."""
    code = _CHILD.replace("{body}", body)
    argv = [sys.executable, "-c", code, kill_at, str(occurrence), str(log or ""), *map(str, args)]
    return subprocess.run(argv, capture_output=True, text=True, timeout=timeout, env=_environment(),
                          cwd=str(cwd or REPO))


def killed(done: subprocess.CompletedProcess) -> bool:
    return done.returncode == -signal.SIGKILL


def write_points(args: Sequence[str | os.PathLike[str]], cwd: Path | None = None) -> list[str]:
    """The write points `grove args` passes, in order (one normal run)."""
    with tempfile.TemporaryDirectory(prefix="grove-points-") as folder:
        log = Path(folder) / "points.txt"
        done = run_grove(args, log=log, cwd=cwd)
        if done.returncode != 0:
            raise AssertionError(f"grove {' '.join(map(str, args))} failed: {done.stderr[-2000:]}")
        return log.read_text().splitlines() if log.exists() else []


def occurrences(points: Sequence[str]) -> list[tuple[str, int]]:
    """(label, n) for every point: kill at the n-th time that label is passed."""
    counts: dict[str, int] = {}
    out = []
    for label in points:
        counts[label] = counts.get(label, 0) + 1
        out.append((label, counts[label]))
    return out


def snapshot(root: Path) -> dict[str, str]:
    """Every entry under root (links as their target, files as a hash), staging entries included."""
    state: dict[str, str] = {}
    if not root.exists():
        return state
    for path in sorted(root.rglob("*")):
        rel = str(path.relative_to(root))
        if path.is_symlink():
            state[rel] = "-> " + os.readlink(path)
        elif path.is_file():
            state[rel] = hashlib.sha256(path.read_bytes()).hexdigest()
        else:
            state[rel] = "dir"
    return state


def staging_left(folder: Path) -> list[str]:
    """Staging entries anywhere under `folder` (what a killed writer leaves until the next run)."""
    if not folder.exists():
        return []
    return sorted(str(p.relative_to(folder)) for p in folder.rglob("*") if STAGING.match(p.name))


def without_staging(state: dict[str, str]) -> dict[str, str]:
    return {rel: value for rel, value in state.items()
            if not any(STAGING.match(part) for part in Path(rel).parts)}


def whole_json_lines(path: Path) -> bool:
    """Every line of a JSON-lines file parses, except that one torn line may stand alone (never glued)."""
    if not path.exists():
        return True
    torn = 0
    for raw in path.read_bytes().splitlines():
        try:
            json.loads(raw)
        except ValueError:
            torn += 1
    return torn <= 1


def matching(points: Sequence[str], pattern: str) -> list[str]:
    return [p for p in points if fnmatch.fnmatch(p, pattern)]


def sweep(args: Sequence[str | os.PathLike[str]], watched: Sequence[Path], *, cwd: Path | None = None,
          limit: int | None = None) -> list[dict]:
    """Kill `grove args` at each of its write points in turn (at most `limit`), each time running it again
    normally afterwards, and say for each point what the watched folders held.

    The command has run once before (the old state); it is deterministic, so the new state is the same
    as the old one and a state with any file missing, extra or different is a torn one. Files that
    differ between two normal runs (a timestamp) are compared by presence only. Returns one dict per
    point: label, n, killed, state ("old or new" / "TORN: ..."), staging left by the kill, and
    whether the next run succeeded and left no staging.
    """
    def state() -> dict[str, dict[str, str]]:
        return {str(folder): without_staging(snapshot(folder)) for folder in watched}

    first = run_grove(args, cwd=cwd)
    if first.returncode != 0:
        raise AssertionError(f"grove {' '.join(map(str, args))} failed: {first.stderr[-2000:]}")
    reference = state()
    points = write_points(args, cwd=cwd)
    again = state()
    volatile = {(folder, rel) for folder, files in reference.items() for rel, digest in files.items()
                if again.get(folder, {}).get(rel) != digest}
    results = []
    for label, n in occurrences(points)[:limit]:
        done = run_grove(args, kill_at=label, occurrence=n, cwd=cwd)
        after = state()
        torn = []
        for folder, files in reference.items():
            got = after.get(folder, {})
            for rel in sorted(set(files) | set(got)):
                if (folder, rel) in volatile:
                    if (rel in files) != (rel in got):
                        torn.append(rel)
                elif files.get(rel) != got.get(rel):
                    torn.append(rel)
        left = sorted({entry for folder in watched for entry in staging_left(folder.parent)})
        rerun = run_grove(args, cwd=cwd)
        clean = rerun.returncode == 0 and not any(staging_left(folder.parent) for folder in watched)
        results.append({"label": label, "n": n, "killed": killed(done),
                        "state": "old or new" if not torn else "TORN: " + ", ".join(torn[:3]),
                        "left": len(left), "next_run_clean": clean})
    return results
