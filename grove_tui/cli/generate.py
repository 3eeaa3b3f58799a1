"""`grove generate`, `grove batch`, `grove simulate`: the generation pipeline without the TUI.

Progress goes to stderr (rich), results to stdout, so `grove generate ... > result.txt` keeps only
what a script needs. They build nothing themselves: a `services.session.GroveSession` does the work.
Exit codes (README): 0 ok, 2 bad input, 3 generation failed, 4 model error, 130 cancelled.
"""

from __future__ import annotations

import json
import re
import sys
from collections.abc import Callable, Mapping
from pathlib import Path
from typing import TYPE_CHECKING, Any, Protocol

import click
from rich.console import Console

from grove_tui.errors import EXIT_BAD_INPUT, EXIT_OK, EXIT_RUNTIME_FAILURE
from grove_tui.services.jobs import SCENARIO_LENGTH
from grove_tui.settings import PEDESTRIAN_MODELS

if TYPE_CHECKING:
    from rich.progress import TaskID
    from rich.status import Status

    from grove_tui.scenario.model import Scenario
    from grove_tui.services.dataset import JobRecord
    from grove_tui.services.jobs import BatchJob
    from grove_tui.services.session import GroveSession, ScenarioRequest


class Generated(Protocol):
    """What a summary reads of a generation's result (generation.pipeline.GenerationResult)."""

    @property
    def scenario(self) -> Scenario: ...
    @property
    def report(self) -> Mapping[str, Any]: ...  # Any: generation.json's report, as the pipeline builds it


def _err() -> Console:
    return Console(file=sys.stderr, highlight=False, soft_wrap=True)


def _out() -> Console:
    return Console(file=sys.stdout, highlight=False, soft_wrap=True)


def _root_options(ctx: click.Context) -> dict[str, str | None]:
    root = ctx.find_root()
    return dict(root.obj or {}) if root.obj is not None else {}


def parse_robot_point(text: str | None) -> tuple[float, float] | str | None:
    """"x,y" -> point; anything else is an RoI name resolved by the pipeline."""
    if text is None or not text.strip():
        return None
    match = re.fullmatch(r"\s*(-?\d+(?:\.\d+)?)\s*,\s*(-?\d+(?:\.\d+)?)\s*", text)
    if match:
        return (float(match.group(1)), float(match.group(2)))
    return text.strip()


def session_for(ctx: click.Context, roi_model: str | None = None, bt_model: str | None = None) -> GroveSession:
    """The run's application session; a subcommand's model options win over the `grove` group's."""
    from grove_tui.services.session import GroveSession

    options = _root_options(ctx)
    return GroveSession(model=options.get("model"), roi_model=roi_model or options.get("roi_model"),
                        bt_model=bt_model or options.get("bt_model"))


class Progress:
    """Stage lines on stderr; token count while the model writes."""

    def __init__(self, console: Console, prefix: str = "", show: Callable[[str], None] | None = None) -> None:
        self.console = console
        self.prefix = prefix
        # Under a batch's progress bar the stage and token count go to `show` (the bar's own line), not to
        # a spinner: rich shows one live display at a time.
        self.show = show
        self.tokens = 0
        self._status: Status | None = None

    def __call__(self, event: object) -> None:
        from grove_tui.services.session import AttemptStarted, StageFinished, StageStarted, TokenStreamed

        if isinstance(event, AttemptStarted):
            self.tokens = 0  # the count is the running attempt's, as the app shows it
            self.console.print(f"{self.prefix}[yellow]{event.stage}[/] attempt {event.attempt} ({event.reason})",
                               markup=True, highlight=False)
        elif isinstance(event, StageStarted):
            self.tokens = 0
            if self.show is not None:
                self.show(f"{self.prefix}{event.stage}...")
            elif self.console.is_terminal:
                self._status = self.console.status(f"{self.prefix}{event.stage}...")
                self._status.start()
        elif isinstance(event, TokenStreamed):
            self.tokens += 1
            if self.show is not None:
                self.show(f"{self.prefix}{event.stage}: {self.tokens} tokens")
            elif self._status is not None:
                self._status.update(f"{self.prefix}{event.stage}: {self.tokens} tokens")
        elif isinstance(event, StageFinished):
            if self._status is not None:
                self._status.stop()
                self._status = None
            tokens = f" ({event.prompt_tokens} prompt + {event.completion_tokens} completion tokens)" \
                if event.prompt_tokens or event.completion_tokens else ""
            self.console.print(f"{self.prefix}[green]{event.stage}[/] {event.seconds:.2f} s{tokens} {event.detail}")

    def stop(self) -> None:
        if self._status is not None:
            self._status.stop()
            self._status = None


def summary_lines(result: Generated, bundle: Path,
                  checked: dict[str, Any] | None = None,  # Any: grounding.json as read; GroundingReport checks it
                  ) -> list[str]:
    scenario, report = result.scenario, result.report
    stages = " ".join(f"{k}={v['seconds']:.2f}s" for k, v in report["stages"].items())
    groups = ", ".join(f"{g['count']} {g['label']} " + (f"across {len(g['spawn_zones'])} zones" if g.get("spawn_zones")
                                                         else f"from {g['spawn']}") for g in report["groups"])
    lines = [
        f"bundle: {bundle}",
        f"agents: {len(scenario.agents)} ({groups})",
        f"zones: {', '.join(report['zones'])}",
        f"tokens: prompt={report['prompt_tokens']} completion={report['completion_tokens']}",
        f"time: total={report['total_seconds']:.2f}s {stages}",
    ]
    if report.get("variation"):
        variation = report["variation"]
        lines.insert(1, f"variation: {variation['index']} of {variation['count']} (seed {scenario.seed}, "
                        f"parent seed {variation['parent_seed']})")
    if scenario.robot is not None:
        r = scenario.robot
        lines.append(f"robot: ({r.start[0]:.2f}, {r.start[1]:.2f}) -> ({r.goal[0]:.2f}, {r.goal[1]:.2f})")
    if report.get("grounding") or checked:
        from grove_tui.scenario.report import GroundingReport

        # What the sentence asked, what the scenario plans, and after a run what the people did.
        grounding = GroundingReport.from_dict(checked or report["grounding"])
        lines.append("grounding: " + grounding.summary())
        lines += ["  " + line for line in grounding.lines()[1:]]
    return lines


@click.command("generate")
@click.option("--no-ui", is_flag=True, help="Generate headless (the only mode of this command; the TUI is `grove`).")
@click.option("--world", "world_name", required=True, help="A shipped world (`grove worlds list`: hospital, office, residential, airport, station, museum, mall) or a path to a world YAML.")
@click.option("--preset", "preset_name", required=True, help="emergency, queuing, normal, vanilla or a user preset.")
@click.option("--prompt", required=True, help="The scenario in one sentence.")
@click.option("--seed", type=click.IntRange(0, 2**32 - 1), default=0, show_default=True,
              help="Seeds the model and every sampler (0 to 2^32-1).")
@click.option("--simulate", "simulate_seconds", type=float, is_flag=False, flag_value=SCENARIO_LENGTH, default=None,
              callback=lambda ctx, param, value: _run_seconds(value, param),
              help="Also simulate this many seconds and write trajectories.csv into the bundle; with no number, "
                   "the scenario's own length (long enough for its planned behaviours, capped; the report says it).")
@click.option("--out", "out_dir", type=click.Path(), required=True,
              help="Bundle folder to write; an existing bundle there is replaced, any other folder is refused.")
@click.option("--overwrite", is_flag=True, help="Replace --out even when it is a folder that is not a bundle.")
@click.option("--roi-model", type=click.Path(dir_okay=False), default=None, help="GGUF for RoI selection.")
@click.option("--bt-model", type=click.Path(dir_okay=False), default=None, help="GGUF for behavior-tree synthesis.")
@click.option("--robot-start", default=None, help="Robot start: 'x,y' or an RoI name (default: chosen across the scene).")
@click.option("--robot-goal", default=None, help="Robot goal: 'x,y' or an RoI name.")
@click.option("--no-robot", is_flag=True, help="Generate without a robot.")
@click.option("--json", "as_json", is_flag=True, help="Print the result as one JSON object on stdout.")
@click.option("--variations", type=click.IntRange(1, 10_000), default=1, show_default=True,
              help="Write N scenarios of the prompt into --out/v000 .. (seeds derived from --seed; v000 uses it).")
@click.option("--strict", is_flag=True,
              help="Refuse (exit 2, with the question) a sentence the reader is unsure of: two places that fit "
                   "alike, a guessed count, an implied group.")
@click.pass_context
def generate(ctx: click.Context, no_ui: bool, world_name: str, preset_name: str, prompt: str, seed: int,
             simulate_seconds: float | None, out_dir: str, overwrite: bool, roi_model: str | None, bt_model: str | None,
             robot_start: str | None, robot_goal: str | None, no_robot: bool, as_json: bool, variations: int,
             strict: bool) -> None:
    """Turn a sentence into a scenario bundle (scenario.yaml, trees, grid, generation.json)."""
    from grove_tui.errors import PromptError
    from grove_tui.services.jobs import variation_suffix
    from grove_tui.services.session import RobotRequest, ScenarioRequest, variation_requests

    robot = RobotRequest(parse_robot_point(robot_start), parse_robot_point(robot_goal), enabled=not no_robot)
    request = ScenarioRequest(world_name, preset_name, prompt, seed, robot)
    if strict:
        from grove_tui.services.session import GroveSession

        questions = GroveSession().unsure(request)  # the reader only: no model loads for this
        if questions:
            raise PromptError("the reading of the sentence is unsure: " + "; ".join(questions),
                              hint="say it plainly (name the place as the world does, give the number), "
                                   "or run without --strict to take the reader's best guess")
    if variations == 1:
        targets = [(request, Path(out_dir))]
    else:
        # --out holds one bundle per variation; each bundle folder is checked like a single --out.
        targets = [(varied, Path(out_dir) / variation_suffix(varied.variation.index, variations).lstrip("-"))
                   for varied in variation_requests(request, variations) if varied.variation is not None]
    with session_for(ctx, roi_model, bt_model) as session:
        for varied, target in targets:
            prefix = f"[{varied.variation.index + 1}/{variations}] " if varied.variation is not None else ""
            _generate_one(session, varied, target, overwrite, simulate_seconds, as_json, prefix)


def _generate_one(session: GroveSession, request: ScenarioRequest, out_dir: Path, overwrite: bool,
                  simulate_seconds: float | None, as_json: bool, prefix: str) -> None:
    progress = Progress(_err(), prefix=prefix)
    try:
        generated = session.generate(request, out_dir, overwrite=overwrite, on_event=progress)
        seconds = None if simulate_seconds == SCENARIO_LENGTH else simulate_seconds
        sim = session.simulate(generated.bundle_dir, seconds).to_dict() if simulate_seconds else None
    except BaseException:
        progress.stop()  # the spinner must not overwrite the error line the grove group prints
        raise
    result, bundle = generated.result, generated.bundle_dir
    if as_json:
        payload = {"bundle": str(bundle), "agents": len(result.scenario.agents), "report": {
            k: result.report[k] for k in ("stages", "total_seconds", "prompt_tokens", "completion_tokens", "zones",
                                          "groups", "notes", "grounding", "variation") if k in result.report}}
        if sim is not None:
            payload["simulation"] = sim
        click.echo(json.dumps(payload))
        return
    out = _out()
    for line in summary_lines(result, bundle, checked=_checked_report(bundle) if sim is not None else None):
        out.print(line, markup=False)
    if sim is not None:
        out.print(f"simulated: {sim['sim_seconds']:.1f} s in {sim['wall_seconds']:.2f} s wall -> "
                  f"{bundle / 'trajectories.csv'}", markup=False)


def _checked_report(bundle: Path) -> dict[str, Any] | None:  # Any: JSON as read; GroundingReport checks it
    """The grounding report the run checked (grounding.json), when the bundle has one."""
    path = bundle / "grounding.json"
    return json.loads(path.read_text(encoding="utf-8")) if path.is_file() else None


@click.command("batch")
@click.argument("jobs_file", type=click.Path(dir_okay=False))
@click.option("--out", "out_dir", type=click.Path(), required=True, help="Folder for the bundles, one per job.")
@click.option("--overwrite", is_flag=True, help="Replace job folders even when they are not bundles.")
@click.option("--resume", is_flag=True,
              help="Skip jobs an earlier run of this --out completed with the same inputs (batch-state.jsonl).")
@click.option("--ray", "ray_address", is_flag=False, flag_value="local", default=None, metavar="[ADDRESS]",
              help="Run the jobs on Ray actors: alone a private local Ray, or `auto` / `host:port` / "
                   "`ray://host:port` for a running cluster (needs ./install.sh cluster).")
@click.option("--workers", type=click.IntRange(1, 100_000), default=None,
              help="Ray actors to start (default: one per CPU of the Ray cluster).")
@click.option("--ray-return", is_flag=True,
              help="With --ray: workers send each job's files back and this process writes them into --out "
                   "(for workers without a shared file system; automatic for a worker that cannot see --out).")
@click.option("--index", "index_format", type=click.Choice(["sqlite", "parquet"]), default="sqlite",
              show_default=True, help="The dataset index: --out/dataset.sqlite, or dataset.parquet (needs pyarrow).")
@click.option("--roi-model", type=click.Path(dir_okay=False), default=None)
@click.option("--bt-model", type=click.Path(dir_okay=False), default=None)
@click.pass_context
def batch(ctx: click.Context, jobs_file: str, out_dir: str, overwrite: bool, resume: bool, ray_address: str | None,
          workers: int | None, ray_return: bool, index_format: str, roi_model: str | None, bt_model: str | None) -> None:
    """Generate many scenarios from a JSONL file, loading the models once (per Ray worker with --ray).

    Each line: {"world": ..., "preset": ..., "prompt": ..., "seed": 0, "name": "optional-dir-name",
    "simulate": optional seconds, "variations": optional N, "refine": optional ["follow-up", ...]}. Every line is checked before any job runs:
    bad lines (and lines whose name another line already uses) are reported with their line numbers and
    skipped, the good ones run. A failed job is recorded (batch-state.jsonl: message and exit code) and
    the batch goes on; --out/dataset.sqlite (or .parquet) indexes every scenario. A progress bar shows
    jobs done, scenarios per hour and time left. Exit code: 2 when any line was refused, else 3 when
    any job failed, else 0.
    """
    from grove_tui.errors import JobFileError
    from grove_tui.services.batch import run_batch
    from grove_tui.services.dataset import check_index_format
    from grove_tui.services.jobs import read_jobs

    err, out = _err(), _out()
    if ray_return and ray_address is None:
        raise click.UsageError("--ray-return sends files from Ray workers: use it with --ray")
    check_index_format(index_format)  # before the job file is read: nothing runs without its index
    if ray_address is not None:
        from grove_tui.services.cluster import require_ray

        require_ray()  # nor without Ray: one error line (exit 2), nothing read or written
    session = session_for(ctx, roi_model, bt_model)
    jobs, problems = read_jobs(jobs_file)
    jobs, refused = session.check_jobs(jobs, Path(out_dir), overwrite)
    problems = sorted(problems + refused, key=lambda p: p.line)
    if not jobs:
        # Nothing runs: one error line naming every refused line, like any other bad input.
        raise JobFileError(f"{jobs_file}: no job can run: " + "; ".join(map(str, problems)))
    for problem in problems:
        err.print(f"error: {jobs_file}:{problem.line}: {problem.message}", markup=False, highlight=False)
    progresses: list[Progress] = []
    bar = _BatchBar(err)

    def events_for(index: int, job: BatchJob) -> Progress:
        # Stage lines print above the bar; a Ray batch's stages run in the workers and print nothing here.
        progresses.append(Progress(err, prefix=f"[{index}/{len(jobs)}] ", show=bar.show))
        return progresses[-1]

    def started(to_run: list[BatchJob], skipped: list[BatchJob]) -> None:
        if skipped:
            err.print(f"resume: {len(skipped)} completed job(s) skipped, {len(to_run)} to run", markup=False)
        bar.start(len(to_run))

    def report(record: JobRecord) -> None:
        if progresses:
            progresses[-1].stop()
        bar.advance()
        bundle = Path(out_dir) / record.name
        if not record.ok:
            out.print(f"failed {bundle} (exit {record.exit_code}) {record.message}", markup=False)
            return
        exports = "".join(f" {kind}={path}" for kind, path in record.exports)
        out.print(f"ok {bundle} agents={record.agents} prompt_tokens={record.prompt_tokens} "
                  f"seconds={record.seconds:.2f}{exports}", markup=False)

    try:
        with session:
            result = run_batch(session, jobs, Path(out_dir), overwrite=overwrite, resume=resume,
                               ray_address=ray_address, workers=workers, ray_return=ray_return,
                               index_format=index_format, on_start=started,
                               events_for=None if ray_address is not None else events_for, on_record=report)
    finally:
        if progresses:
            progresses[-1].stop()
        bar.stop()
    done = len(result.records) - result.failures + len(result.skipped)
    total = len(jobs) + len(problems)
    err.print(f"{done}/{total} scenarios generated; index: {result.index}")
    ctx.exit(EXIT_BAD_INPUT if problems else EXIT_RUNTIME_FAILURE if result.failures else EXIT_OK)


class _BatchBar:
    """A rich progress bar for a batch: jobs done, scenarios per hour, time left."""

    def __init__(self, console: Console) -> None:
        from rich.progress import BarColumn, MofNCompleteColumn, Progress as RichProgress, TextColumn, \
            TimeElapsedColumn, TimeRemainingColumn

        self._progress = RichProgress(TextColumn("batch"), BarColumn(), MofNCompleteColumn(),
                                      TextColumn("{task.fields[rate]}"), TimeElapsedColumn(), TextColumn("ETA"),
                                      TimeRemainingColumn(), TextColumn("{task.fields[now]}"), console=console,
                                      transient=False)
        self._task: TaskID | None = None

    def start(self, total: int) -> None:
        self._task = self._progress.add_task("batch", total=total, rate="", now="")
        self._progress.start()

    def show(self, text: str) -> None:
        """What the running job does now (one-process batch: its stage and tokens)."""
        if self._task is not None:
            self._progress.update(self._task, now=text)

    def advance(self) -> None:
        if self._task is None:
            return
        self._progress.advance(self._task)
        task = self._progress.tasks[0]
        if task.elapsed:
            per_hour = task.completed / task.elapsed * 3600
            self._progress.update(self._task, rate=f"{per_hour:.0f} scenarios/h", now="")

    def stop(self) -> None:
        self._progress.stop()


def _run_seconds(value: float | None, param: click.Parameter) -> float | None:
    """`--simulate`: a number of seconds (0 to a day; 0 runs nothing) or none, the scenario's length."""
    if value is None or value == SCENARIO_LENGTH:
        return value
    _finite(value, param)
    if not 0.0 <= value <= 24 * 3600.0:
        raise click.BadParameter(f"{value:g} is not between 0 and {24 * 3600} seconds", param=param)
    return value


def _finite(value: float | None, param: click.Parameter) -> float | None:
    import math

    if value is not None and not math.isfinite(value):
        raise click.BadParameter(f"{value} is not a finite number of seconds", param=param)
    return value


@click.command("simulate")
@click.argument("bundle", type=click.Path(file_okay=False))
@click.option("--seconds", type=click.FloatRange(min=0.0, min_open=True, max=24 * 3600.0), default=None,
              callback=lambda ctx, param, value: _finite(value, param),
              help="Simulated seconds to run (at most a day); default the scenario's own length, long enough "
                   "for its planned behaviours.")
@click.option("--model", type=click.Choice(PEDESTRIAN_MODELS), default=None,
              help="Pedestrian model: grove (passes RiMEA) or lightsfm (HuNavSim's forces); "
                   "default the settings' simulation.pedestrian_model.")
@click.pass_context
def simulate(ctx: click.Context, bundle: str, seconds: float | None, model: str | None) -> None:
    """Simulate a bundle and write trajectories.csv into it."""
    out = _out()
    with session_for(ctx) as session:
        sim = session.simulate(Path(bundle), seconds, model=model).to_dict()
    out.print(f"simulated: {sim['sim_seconds']:.1f} s in {sim['wall_seconds']:.2f} s wall -> "
              f"{Path(bundle) / 'trajectories.csv'}", markup=False)
    for key, value in sim["counters"].items():
        out.print(f"{key}: {value}", markup=False)
    checked = _checked_report(Path(bundle))
    if checked is not None:
        from grove_tui.scenario.report import GroundingReport

        grounding = GroundingReport.from_dict(checked)
        out.print("grounding: " + grounding.summary(), markup=False)
        for line in grounding.lines()[1:]:
            out.print("  " + line, markup=False)
