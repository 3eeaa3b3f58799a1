"""`grove generate --no-ui`, `grove batch`, `grove simulate`: exit codes, stdout/stderr split, no partial bundles.

Bad input is refused before any model runs; the success paths generate with the embedded model.
"""

from __future__ import annotations

import json

import pytest
from click.testing import CliRunner

from grove_tui.cli import main
from grove_tui.errors import EXIT_BAD_INPUT, EXIT_MODEL_ERROR, EXIT_OK, EXIT_RUNTIME_FAILURE as EXIT_GENERATION_FAILED
from grove_tui.cli.generate import (
                                    parse_robot_point)
from grove_tui.scenario.bundle import load_bundle
from grove_tui.llm.embedded import embedded_model_path


@pytest.fixture(scope="module")
def embedded_path() -> str:
    return str(embedded_model_path())


def invoke(args: list[str]):
    return CliRunner().invoke(main, args, catch_exceptions=False)


def generate_args(out, embedded_path, world="hospital", preset="queuing", prompt="Six patients queue at the pharmacy counter",
                  extra=()):
    return ["generate", "--no-ui", "--world", world, "--preset", preset, "--prompt", prompt, "--out", str(out),
            "--bt-model", embedded_path, *extra]


@pytest.mark.parametrize("world, preset, prompt, message", [
    ("moonbase", "queuing", "Six patients queue", "no shipped world"),
    ("hospital", "panic", "Six patients queue", "unknown preset 'panic'"),
    ("hospital", "queuing", "   ", "the prompt is empty"),
    # These two start the model before the sentence is refused.
    pytest.param("hospital", "normal", "Ten patients swim in the swimming pool", "does not have: 'swimming pool'",
                 marks=pytest.mark.slow),
    pytest.param("hospital", "normal", "10,000 people crowd into the bathroom", "10000 people do not fit",
                 marks=pytest.mark.slow),
])
def test_bad_input_exits_2_with_a_clear_message_and_no_bundle(tmp_path, embedded_path, world, preset, prompt, message):
    out = tmp_path / "bundle"
    result = invoke(generate_args(out, embedded_path, world, preset, prompt))
    assert result.exit_code == EXIT_BAD_INPUT
    assert message in result.stderr
    assert result.stdout == ""
    assert not out.exists() and list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("prompt, message, hint", [
    ("   ", "the prompt is empty", "Say who is there, how many and what they do"),
    ("people walk " * 200, "characters long", "Say it in one or two sentences"),
], ids=["empty", "overlong"])
def test_an_empty_or_overlong_prompt_gets_a_hint_about_itself(tmp_path, embedded_path, prompt, message, hint):
    result = invoke(generate_args(tmp_path / "bundle", embedded_path, prompt=prompt))
    assert result.exit_code == EXIT_BAD_INPUT
    assert message in result.stderr and hint in result.stderr
    assert "fewer people" not in result.stderr
    assert not (tmp_path / "bundle").exists()


@pytest.mark.slow
def test_world_by_path(tmp_path, embedded_path):
    from grove_tui.paths import worlds_dir

    out = tmp_path / "bundle"
    result = invoke(generate_args(out, embedded_path, world=str(worlds_dir() / "office.yaml"), preset="normal",
                                  prompt="Ten people swim in the swimming pool"))
    # the world loaded from its path: the error is about the prompt, not the world
    assert result.exit_code == EXIT_BAD_INPUT and "world 'office' does not have" in result.stderr


def test_model_that_is_not_a_gguf_exits_4(tmp_path):
    fake = tmp_path / "model.gguf"
    fake.write_bytes(b"not a model at all")
    result = invoke(generate_args(tmp_path / "bundle", str(fake)))
    assert result.exit_code == EXIT_MODEL_ERROR
    assert "model.gguf" in result.stderr
    assert not (tmp_path / "bundle").exists()


def test_strict_refuses_an_unsure_reading_with_the_question_and_writes_nothing(tmp_path, embedded_path):
    # "the counter": the hospital has the pharmacy's and the cafeteria's; no model loads to say so
    out = tmp_path / "bundle"
    result = invoke(generate_args(out, embedded_path, prompt="Ten people queue at the counter", extra=["--strict"]))
    assert result.exit_code == EXIT_BAD_INPUT
    assert "unsure" in result.stderr and "pharmacy" in result.stderr and "food_counter" in result.stderr
    assert "without --strict" in result.stderr
    assert not out.exists() and list(tmp_path.iterdir()) == []


def test_robot_points_parse():
    assert parse_robot_point("3.5, -2") == (3.5, -2.0)
    assert parse_robot_point("main_entrance") == "main_entrance"
    assert parse_robot_point(" ") is None


@pytest.mark.slow
def test_generate_simulate_and_resimulate(tmp_path, embedded_path):
    out = tmp_path / "pharmacy"
    result = invoke(generate_args(out, embedded_path, extra=["--simulate", "5", "--seed", "2", "--robot-start", "main_entrance"]))
    assert result.exit_code == EXIT_OK, result.stderr
    lines = result.stdout.splitlines()
    assert lines[0] == f"bundle: {out}"
    assert any(line.startswith("agents: 6 ") for line in lines)
    assert any(line.startswith("simulated: 5.0 s") for line in lines)
    # after a run the report is the checked one, with the run it was checked on
    assert any(line.startswith("grounding: ") and "(run of 5 s)" in line for line in lines), lines
    assert (out / "grounding.json").is_file()
    assert "synthesis" in result.stderr  # progress went to stderr
    scenario, trees, _, _ = load_bundle(out)
    assert len(scenario.agents) == 6 and scenario.seed == 2 and len(trees) == 6
    header = (out / "trajectories.csv").read_text().splitlines()[0]
    assert header == "frame,t,id,x,y,vx,vy,yaw,group"
    first = (out / "trajectories.csv").read_text()
    again = invoke(["simulate", str(out), "--seconds", "5"])
    assert again.exit_code == EXIT_OK, again.stderr
    assert (out / "trajectories.csv").read_text() == first  # the bundle simulates identically


@pytest.mark.slow
def test_simulate_with_no_number_runs_the_scenarios_own_length(tmp_path, embedded_path):
    out = tmp_path / "pharmacy"
    # `--simulate` just before `--seed`: the option takes no number and the next option is not eaten
    result = invoke(generate_args(out, embedded_path, extra=["--simulate", "--seed", "2"]))
    assert result.exit_code == EXIT_OK, result.stderr
    simulated = [line for line in result.stdout.splitlines() if line.startswith("simulated: ")]
    assert simulated, result.stdout
    seconds = float(simulated[0].split()[1])
    assert 60.0 <= seconds <= 900.0  # the scenario's length: at least a minute, capped
    rows = (out / "trajectories.csv").read_text().splitlines()
    assert float(rows[-1].split(",")[1]) == pytest.approx(seconds, abs=0.5)
    again = invoke(["simulate", str(out)])  # and `grove simulate` with no --seconds runs the same length
    assert again.exit_code == EXIT_OK, again.stderr
    assert any(line.startswith(f"simulated: {seconds:.1f} s") for line in again.stdout.splitlines()), again.stdout


@pytest.mark.slow
def test_batch_loads_once_and_reports_each_line(tmp_path, embedded_path):
    jobs = tmp_path / "jobs.jsonl"
    jobs.write_text("\n".join([
        json.dumps({"world": "residential", "preset": "normal", "prompt": "Two children walk to the kitchen",
                    "seed": 0, "name": "kids"}),
        json.dumps({"world": "hospital", "preset": "normal", "prompt": "Ten people swim in the swimming pool",
                    "name": "pool"}),
    ]) + "\n")
    out = tmp_path / "out"
    result = invoke(["batch", str(jobs), "--out", str(out), "--bt-model", embedded_path])
    assert result.exit_code == EXIT_GENERATION_FAILED  # one line failed, the other was generated
    assert f"ok {out / 'kids'} agents=2" in result.stdout
    assert f"failed {out / 'pool'}" in result.stdout and "swimming pool" in result.stdout
    assert (out / "kids" / "scenario.yaml").is_file() and not (out / "pool").exists()
    assert "1/2 scenarios generated" in result.stderr


def test_batch_file_errors_exit_2(tmp_path, embedded_path):
    jobs = tmp_path / "jobs.jsonl"
    jobs.write_text('{"world": "hospital", "preset": "normal"}\n')
    result = invoke(["batch", str(jobs), "--out", str(tmp_path / "out"), "--bt-model", embedded_path])
    assert result.exit_code == EXIT_BAD_INPUT and "missing prompt" in result.stderr
    jobs.write_text("{not json\n")
    result = invoke(["batch", str(jobs), "--out", str(tmp_path / "out"), "--bt-model", embedded_path])
    assert result.exit_code == EXIT_BAD_INPUT and "not valid JSON" in result.stderr


def test_simulate_a_missing_bundle_exits_2(tmp_path):
    result = invoke(["simulate", str(tmp_path / "nothing"), "--seconds", "1"])
    assert result.exit_code == EXIT_BAD_INPUT and "no such bundle directory" in result.stderr


def test_progress_says_when_the_model_is_asked_again():
    import io

    from rich.console import Console

    from grove_tui.cli.generate import Progress
    from grove_tui.generation.pipeline import AttemptStarted, StageStarted, TokenStreamed

    console = Console(file=io.StringIO(), width=100, record=True)
    progress = Progress(console)
    progress(StageStarted("synthesis"))
    for _ in range(3):
        progress(TokenStreamed("synthesis", "x"))
    progress(AttemptStarted("synthesis", 2, "cut off at 512 tokens"))
    assert progress.tokens == 0, "the token count is the running attempt's"
    assert "synthesis attempt 2 (cut off at 512 tokens)" in console.export_text()
