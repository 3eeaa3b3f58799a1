"""A real terminal for the app's end-to-end tests: tmux runs a command, the test types and reads the
screen back (tests/tui/test_tui_e2e*.py)."""

from __future__ import annotations

import os
import re
import shlex
import shutil
import subprocess
import time
import uuid
from pathlib import Path

TMUX = shutil.which("tmux")
WIDTH, HEIGHT = 120, 40


class Terminal:
    def __init__(self, command: str, env: dict[str, str], width: int = WIDTH, height: int = HEIGHT) -> None:
        self.name = f"grove-e2e-{uuid.uuid4().hex[:8]}"
        exports = " ".join(f"{k}={shlex.quote(v)}" for k, v in env.items())
        # `sleep` keeps the pane readable if grove exits early, so the failure shows what it printed.
        script = f"env {exports} {command}; echo GROVE-EXITED $?; sleep 60"
        subprocess.run([TMUX, "new-session", "-d", "-s", self.name, "-x", str(width), "-y", str(height), script],
                       check=True)

    def screen(self) -> str:
        out = subprocess.run([TMUX, "capture-pane", "-p", "-t", self.name], capture_output=True, text=True)
        return out.stdout

    def keys(self, *keys: str, literal: bool = False) -> None:
        args = [TMUX, "send-keys", "-t", self.name] + (["-l"] if literal else []) + list(keys)
        subprocess.run(args, check=True)

    def wait_for(self, pattern: str, timeout: float, what: str) -> re.Match[str]:
        deadline = time.monotonic() + timeout
        while True:
            text = self.screen()
            match = re.search(pattern, text)
            if match:
                return match
            if "GROVE-EXITED" in text or time.monotonic() > deadline:
                raise AssertionError(f"waiting for {what} ({pattern!r}); the screen shows:\n{text}")
            time.sleep(0.1)

    def press(self, *keys: str, pause: float = 0.12) -> None:
        """Keys one at a time, as a person presses them: after Escape a terminal reads a key sent at
        once as alt+key, so every key gets its own moment."""
        for key in keys:
            subprocess.run([TMUX, "send-keys", "-t", self.name, key], check=True)
            time.sleep(pause)

    def type(self, text: str) -> None:
        subprocess.run([TMUX, "send-keys", "-t", self.name, "-l", text], check=True)

    def wait_until(self, condition, timeout: float, what: str) -> str:  # noqa: ANN001 - a screen -> bool check
        """Poll until `condition(screen)` holds; the screen that satisfied it."""
        deadline = time.monotonic() + timeout
        while True:
            text = self.screen()
            if condition(text):
                return text
            if "GROVE-EXITED" in text or time.monotonic() > deadline:
                raise AssertionError(f"waiting for {what}; the screen shows:\n{text}")
            time.sleep(0.1)

    def close(self) -> None:
        subprocess.run([TMUX, "kill-session", "-t", self.name], capture_output=True)


def grove_env(tmp_path: Path, config: str) -> dict[str, str]:
    config_dir = tmp_path / "config"
    config_dir.mkdir(exist_ok=True)
    (config_dir / "config.yaml").write_text(config, encoding="utf-8")
    env = {
        "GROVE_CONFIG_DIR": str(config_dir),
        "GROVE_DATA_DIR": str(tmp_path / "data"),
        "TERM": "xterm-256color",
        "HF_HUB_OFFLINE": "1",
        "TRANSFORMERS_OFFLINE": "1",
    }
    # The retrieval index lives in the user's cache, built once per machine, as for any `grove` user.
    if os.environ.get("GROVE_TEST_CACHE_DIR"):
        env["GROVE_CACHE_DIR"] = os.environ["GROVE_TEST_CACHE_DIR"]
    # A worktree's code, when the tests run with PYTHONPATH pointing at it (the command is installed editable).
    if os.environ.get("PYTHONPATH"):
        env["PYTHONPATH"] = os.environ["PYTHONPATH"]
    return env


def simulated_time(screen: str) -> float:
    match = re.search(r"t =\s+([0-9.]+) s", screen)
    return float(match.group(1)) if match else -1.0


def panel(screen: str, title: str) -> list[str]:
    """The text rows inside the box whose top border carries `title` (border characters stripped)."""
    rows = screen.splitlines()
    for top, row in enumerate(rows):
        at = row.find(f"─ {title}")
        if at < 0:
            continue
        left = row.rfind("╭", 0, at)
        right = row.find("╮", at)
        inside = []
        for below in rows[top + 1:]:
            if left >= len(below) or below[left] in "╰":
                break
            inside.append(below[left + 1:right].rstrip("│ ").rstrip())
        return inside
    raise AssertionError(f"no panel titled {title!r} on the screen:\n{screen}")


def prompt_box(screen: str) -> str:
    """The sentence in the setup screen's prompt box, its wrapped lines joined."""
    lines = []
    inside = False
    for row in screen.splitlines():
        if row.startswith("▊▔"):
            inside = True
            continue
        if row.startswith("▊▁"):
            break
        if inside and row.startswith("▊"):
            lines.append(row[1:row.index("▎")].strip())
    text = " ".join(line for line in lines if line)
    return "" if text.startswith("Describe the crowd…") else text  # the empty box's placeholder
