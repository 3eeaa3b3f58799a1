"""End to end in a real 80x24 terminal: tmux runs the installed `grove`, a scenario is generated with the
embedded model, then edited by follow-ups typed in the inspect screen's box: add a group (the model
writes it), change one (no model), remove one, and undo. Needs tmux and the installed `grove` command,
like tests/tui/test_tui_e2e.py, and its terminal driver (tests/helpers/terminal.py)."""

from __future__ import annotations

import re
import shlex
import shutil

import pytest
from helpers.terminal import TMUX, Terminal, grove_env

GROVE = shutil.which("grove")

pytestmark = [
    pytest.mark.slow,
    pytest.mark.skipif(TMUX is None, reason="tmux is not installed; CI must run `apt-get install -y tmux`"),
    pytest.mark.skipif(GROVE is None, reason="the `grove` command is not installed (pip install -e .)"),
]


def follow_up(terminal: Terminal, sentence: str, diff: str, agents: int, timeout: float) -> None:
    """Type a follow-up, see its diff before anything is applied, apply it, see the new scenario."""
    terminal.keys(sentence, literal=True)
    terminal.keys("Enter")
    terminal.wait_for(re.escape(diff), 60, f"the diff of '{sentence}'")
    assert "Enter applies" in terminal.screen()
    terminal.keys("Enter")
    terminal.wait_for(rf"Trees · {agents} agents", timeout, f"the scenario after '{sentence}'")


def test_add_change_remove_and_undo_by_follow_ups_at_80x24(tmp_path):
    env = grove_env(tmp_path, "generation:\n  world: hospital\n  preset: queuing\n")
    terminal = Terminal(shlex.quote(GROVE or "grove"), env, 80, 24)
    try:
        terminal.wait_for(r"Map: hospital", 60, "the setup screen with the hospital map")
        terminal.keys("ten patients queue at the pharmacy counter", literal=True)
        terminal.keys("Enter")
        terminal.wait_for(r"Trees · 10 agents", 900, "the inspect screen")
        assert "follow-up ›" in terminal.screen()

        terminal.keys("f")
        terminal.wait_for(r"Back to the trees", 10, "the follow-up box focused (its keys in the footer)")
        follow_up(terminal, "add a cleaner mopping the corridor", "+ cleaner ×1: wander in main_corridor", 11, 600)
        follow_up(terminal, "make the queue twice as long", "~ patient: ×10 → ×20", 21, 120)
        follow_up(terminal, "remove the cleaner", "- cleaner ×1", 20, 120)
        assert not re.search(r"[▶▼] cleaner ×1", terminal.screen())  # no cleaner group in the trees

        terminal.keys("C-z")
        # The notice first: it shows for a few seconds while the tree count stays, so on a loaded machine
        # waiting for the count first can miss the notice's whole life.
        terminal.wait_for(r"Undid: remove the cleaner", 30, "the undo notice")
        terminal.wait_for(r"Trees · 21 agents", 30, "the cleaner back after ctrl+z")
        runs = sorted((tmp_path / "data" / "runs").iterdir())
        assert len(runs) == 4  # the generation and one bundle per follow-up: undo goes back to one of them

        terminal.keys("C-q")
        terminal.wait_for(r"GROVE-EXITED 0", 20, "a clean exit")
    finally:
        terminal.close()
