"""Issue 31 end to end at 80x24: the app in a real terminal (tmux), typed at as a person types.

The app, worlds, presets, pipeline, simulation and metrics are the real ones; the model is scripted
(tests/helpers/fake_grove.py: a fixed draft, with a loading time and a token pace set per session)
because these tests are about the app. One session walks a user's path through several checks, in
order: a first generation asked before the lists are in, the inspect and simulation screens at
80x24, a regenerate cancelled and one finished, then editing the prompt back on setup. A second
start checks what the app remembers, a reopened run and quitting while the model loads. The real
embedded model's quit and full path are in test_tui_e2e.py.
"""

from __future__ import annotations

import re
import shlex
import sys
import time

import pytest
from helpers.paths import REPO
from helpers.terminal import TMUX, Terminal, assert_quits_quickly, grove_env, panel, prompt_box, simulated_time

pytestmark = pytest.mark.skipif(TMUX is None, reason="tmux is not installed; CI must run `apt-get install -y tmux`")

FAKE_GROVE = f"{shlex.quote(sys.executable)} {shlex.quote(str(REPO / 'tests' / 'helpers' / 'fake_grove.py'))}"
PROMPT = "six patients queue at the pharmacy counter"
LONG = ("ten patients queue at the pharmacy counter while two nurses talk in the waiting area and a family of "
        "four walks from the entrance to the cafeteria past the reception desk")


def counters_time(screen: str) -> float:
    match = re.search(r"Counters · t = ([0-9.]+) s", screen)
    return float(match.group(1)) if match else -1.0


def grove_config(tmp_path) -> dict[str, str]:
    # The config file names another world and preset: what a later start opens on is what it remembers.
    return grove_env(tmp_path, f"generation:\n  world: airport\n  preset: normal\nexport:\n  directory: "
                               f"{tmp_path / 'exports'}\n")


def fake_grove(tmp_path, *options: str) -> Terminal:
    return Terminal(" ".join([FAKE_GROVE, *options]), grove_config(tmp_path), 80, 24)


@pytest.mark.slow
def test_a_user_path_at_80x24(tmp_path):
    terminal_env = grove_config(tmp_path)
    # Listing the worlds takes 2 s and loading the model 4 s, as on a loaded machine's first start;
    # each token 0.15 s, so a regenerate can be cancelled while it writes.
    terminal = fake_grove(tmp_path, "--world", "hospital", "--preset", "queuing", "--list-seconds", "2",
                          "--load-seconds", "4", "--token-seconds", "0.15")
    try:
        # Progress from the first second: the warm-up's step counts down from what it is expected to take,
        # while the world list is still on its way.
        screen = terminal.wait_for(r"~\d+s loading the models", 20, "the warm-up's ETA").string
        # Enter before the world list is in: the request waits for it instead of being refused.
        assert "Map: hospital" not in screen
        terminal.type(PROMPT)
        terminal.press("Enter")
        screen = terminal.wait_for(r"Loading +running", 20, "the generation's loading stage").string
        assert "Choose a world" not in screen
        terminal.wait_for(r"Loading +running .*ETA ~\d+s", 10, "the loading stage's ETA")
        terminal.wait_for(r"Trees · 6 agents", 60, "the inspect screen")
        screen = terminal.wait_for(r"ab\.=shortened", 5, "the map's legend, laid out").string

        # Inspect at 80x24: where each agent goes (its last goal, not the zone it starts in), rows cut
        # with "…", shortened map names explained.
        screen = terminal.wait_for(r"→ pharmacy_counter", 5, "the first agent's destination").string
        trees = panel(screen, "Trees · 6 agents")
        assert any(row.endswith("…") for row in trees), trees
        assert re.search(r" [a-z]+\. ", screen), "a shortened zone name"

        # Regenerate, then Escape while the model writes: back to the scenario you had.
        terminal.press("g")
        terminal.wait_for(r"seed 1", 20, "the regenerate")
        terminal.wait_for(r"Tree synthesis +running", 20, "the model writing")
        terminal.press("Escape")
        terminal.wait_for(r"Generation cancelled", 20, "the cancel's notice")
        screen = terminal.wait_for(r"Trees · 6 agents", 5, "the scenario you had").string
        assert "f2 Worlds" not in screen, "back on setup, not on the scenario"
        # Regenerate again and let it finish: the new scenario replaces the old one here.
        terminal.press("g")
        terminal.wait_for(r"seed 1", 20, "the second regenerate")
        terminal.wait_for(r"Trees · 6 agents", 60, "the regenerated scenario")

        # Simulation at 80x24, played at 8x: the live tree keeps its rows, the counters fold into one line
        # and say the time they are for, at most one second of wall time behind the clock.
        terminal.press("p")
        terminal.wait_for(r"paused", 60, "the simulation")
        terminal.press("]", "]", "]", "Space")
        screen = terminal.wait_until(lambda s: "Sequence" in s and "Counters · t =" in s, 20, "tree and counters")
        tree = panel(screen, "Agent 1")
        assert len(tree) >= 6 and any("Sequence" in row for row in tree), tree
        counters = panel(screen, "Counters · t =")
        assert len(counters) == 1 and counters[0].endswith("…"), counters
        lags = []
        # Four wall seconds at 8x (about 32 simulated): the six patients are all served by about t = 70 s, and
        # the pause below needs a run still playing.
        deadline = time.monotonic() + 4
        while time.monotonic() < deadline:
            screen = terminal.screen()
            assert "done at t" not in screen and "out at t" not in screen, "the run ended before the pause"
            clock, measured = simulated_time(screen), counters_time(screen)
            if clock > 0 and measured >= 0:
                lags.append(clock - measured)
            time.sleep(0.3)
        assert len(lags) > 5 and max(lags) <= 8.0, lags  # 8 simulated seconds: one wall second at 8x
        terminal.press("Space")
        screen = terminal.wait_until(lambda s: "paused" in s and counters_time(s) == round(simulated_time(s), 2),
                                     1.5, "the paused instant's counters within a second")
        # As fast as it goes: the run ends by itself once everyone is done, and says so.
        terminal.press("f", "Space")
        screen = terminal.wait_for(r"■ all 6 (done|out) at t = \d+ s", 60, "the run's end").string
        assert "paused" in screen
        ended = simulated_time(screen)
        time.sleep(1.0)
        assert simulated_time(terminal.screen()) == ended, "the clock stopped at the end"

        # Back to setup: it shows the scenario's world, preset, prompt and seed (1, the regenerate's).
        terminal.press("Escape")
        terminal.wait_for(r"Trees · 6 agents", 10, "inspect")
        terminal.press("Escape")
        terminal.wait_for(r"Leave this scenario", 10, "the question")
        terminal.press("y")
        terminal.wait_until(lambda s: re.search(r"seed▊\s+1 ", s) and prompt_box(s) == PROMPT, 10,
                            "setup with the scenario's prompt and seed 1")

        # Editing keeps readline's keys: ctrl+w and alt+backspace delete a word, ctrl+u to the start.
        def prompt_is(text: str) -> str:
            return terminal.wait_until(lambda s: prompt_box(s) == text, 3, f"the prompt to read {text!r}")

        terminal.press("C-e", "C-w")
        prompt_is("six patients queue at the pharmacy")
        terminal.press("M-BSpace")
        prompt_is("six patients queue at the")
        terminal.press("C-a")
        terminal.type("now ")
        terminal.press("C-e")
        terminal.type("bank")  # as in a shell, the deleted word's space before it stays
        prompt_is("now six patients queue at the bank")
        terminal.press("C-u")
        prompt_is("")
        # Picking a world and a preset leaves the prompt as it was, the cursor at its end.
        terminal.type("ten patients queue at")
        prompt_is("ten patients queue at")
        terminal.press("F2", "Down", "Enter", "C-r", "Down", "Enter")
        terminal.type(" the pharmacy")
        terminal.wait_until(lambda s: "Map: " in s and "Map: hospital" not in s, 10, "the next world picked")
        screen = prompt_is("ten patients queue at the pharmacy")
        # The box grows to show a long sentence whole (up to four lines), and Up brings back the last one.
        terminal.press("C-u")
        terminal.type(LONG)
        screen = prompt_is(LONG)
        assert 2 <= sum(row.startswith("▊ ") for row in screen.splitlines()) <= 4
        terminal.press("C-u", "Up")
        prompt_is(PROMPT)
        # F1 lists the worlds key, and the footer shows it.
        assert "f2 Worlds" in screen and "^w" not in screen.splitlines()[-1]
        terminal.press("F1")
        terminal.wait_for(r"Prompt", 10, "help")
        for _ in range(6):  # page down to the keys table
            if re.search(r"f2 +Worlds +setup\.worlds", terminal.screen()):
                break
            terminal.press("NPage", pause=0.3)
        terminal.wait_for(r"f2 +Worlds +setup\.worlds", 5, "the worlds key in help")
        terminal.press("Escape")

        assert_quits_quickly(terminal, terminal_env, 80, 24, "setup, everything loaded")
    finally:
        terminal.close()

    # The next start (no --world, the config says airport) opens on the last generation's world, preset
    # and seed; a reopened run's Escape
    # shows that run on setup; quit while the model still loads (30 s here) takes under a second.
    terminal = fake_grove(tmp_path, "--load-seconds", "30")
    try:
        screen = terminal.wait_for(r"Map: hospital", 20, "the remembered world").string
        assert re.search(r"seed▊\s+1 ", screen) and "Queues" in screen, screen  # queuing's description
        terminal.press("C-o")
        terminal.wait_for(r"seed 1 · 6 agents", 20, "the recent runs")
        terminal.press("Enter")
        terminal.wait_for(r"Trees · 6 agents", 20, "the reopened run")
        terminal.press("Escape")
        terminal.wait_for(r"f2 Worlds", 10, "setup")
        # setup shows the run's choices when it resumes, a frame after it is back on screen
        screen = terminal.wait_until(lambda s: prompt_box(s) == PROMPT and "Map: hospital" in s, 3,
                                     "the reopened run's prompt and world on setup")
        assert "loading the models" in screen
        assert_quits_quickly(terminal, terminal_env, 80, 24, "while the model loads")
    finally:
        terminal.close()
