"""Batch job files: one JSON object per line, every line checked before any job runs.

    {"world": "hospital", "preset": "queuing", "prompt": "...", "seed": 1, "name": "pharmacy", "simulate": 60,
     "export": ["rosbag", "foxglove"], "variations": 4, "refine": ["add a cleaner mopping the corridor"]}

A job with "refine": [...] edits its scenario by each follow-up in turn (`GroveSession.refine`) before
it is simulated and exported; its bundle is the last step's, with every step in its history.

A job with "variations": N stands for N jobs (bundles NAME-v000 .. NAME-v{N-1}) whose seeds derive
from its seed (`variation_seed`); variation 0 keeps the job's own seed, so it is the plain job's bundle.

A bad line (not JSON, a missing or misspelled key, a value of the wrong type or out of range, text that
is not Unicode, a name another line already uses or that the batch's own files use) is reported with
its line number and skipped; the good lines still run.
"""

from __future__ import annotations

import difflib
import hashlib
import json
import math
import re
from dataclasses import dataclass, replace
from pathlib import Path

from grove_tui.errors import JobFileError
from grove_tui.generation.requests import MAX_PROMPT_CHARS, SCENARIO_LENGTH
from grove_tui.jsontypes import JSONObject
from grove_tui.services.dataset import INDEX_FILE, PARQUET_FILE, STATE_FILE
from grove_tui.services.exporting import EXPORT_FORMATS, EXPORT_SUFFIXES, NEEDS_RUN

MAX_JOB_FILE_BYTES = 64 * 1024 * 1024
MAX_SEED = 2**32 - 1
MAX_SIMULATE_SECONDS = 24 * 3600.0
REQUIRED = ("world", "preset", "prompt")
OPTIONAL = ("seed", "name", "simulate", "export", "variations", "refine")
MAX_FOLLOWUPS = 20
# A generous bound that still refuses a typo like 1e9 before it expands into a billion jobs.
MAX_VARIATIONS = 10_000
# What `export` may list: the `grove export` formats (services.exporting, the one list). All but hunav
# read the simulated run.
EXPORT_KINDS = EXPORT_FORMATS
# What a batch writes into its --out beside the bundles: no job's bundle may take one of these names.
BATCH_FILES = (STATE_FILE, INDEX_FILE, PARQUET_FILE)


@dataclass(frozen=True)
class BatchJob:
    line: int
    world: str
    preset: str
    prompt: str
    seed: int
    name: str  # the bundle folder's name inside the batch's --out, unique in the file
    simulate: float | None
    exports: tuple[str, ...] = ()  # formats to write after the job, in the order given
    variation: Variation | None = None  # set when the line asked for variations
    refine: tuple[str, ...] = ()  # follow-ups applied in turn after generating


@dataclass(frozen=True)
class Variation:
    """Which of the N variations of one prompt a scenario is; recorded in its generation.json."""

    index: int
    count: int
    parent_seed: int  # the seed the line (or `grove generate --seed`) gave; index 0 uses it as is

    def to_dict(self, prompt: str) -> JSONObject:
        return {"index": self.index, "count": self.count, "parent_prompt": prompt, "parent_seed": self.parent_seed}


def variation_seed(seed: int, index: int) -> int:
    """The seed of variation `index` of `seed`: the same pair always gives the same seed.

    Every sampler of the pipeline (the reader's vague counts and place choices, the models, spawn
    points, timing) draws from the scenario seed, so a new seed varies all that the sentence leaves
    open and nothing it fixes. A hash, not seed + index, so that variations of seeds 1 and 2 don't overlap.
    """
    if index == 0:
        return seed
    digest = hashlib.blake2b(f"grove-variation:{seed}:{index}".encode(), digest_size=4).digest()
    return int.from_bytes(digest, "big")


def variation_suffix(index: int, count: int) -> str:
    return f"-v{index:0{max(3, len(str(count - 1)))}d}"


def check_variations(value: object) -> int:
    if isinstance(value, bool) or not isinstance(value, int):
        raise ValueError(f"variations must be a whole number, got {value!r}")
    if not 1 <= value <= MAX_VARIATIONS:
        raise ValueError(f"variations must be between 1 and {MAX_VARIATIONS}, got {value}")
    return value


@dataclass(frozen=True)
class JobProblem:
    line: int
    message: str

    def __str__(self) -> str:
        return f"line {self.line}: {self.message}"


def folder_name(text: str) -> str:
    """A folder name made of `text`'s letters, digits, dots, dashes and underscores."""
    cleaned = re.sub(r"[^A-Za-z0-9._-]+", "-", str(text)).strip("-.")
    return cleaned[:120] or "scenario"


def check_folder_name(name: str) -> str:
    """A bundle name that none of the batch's own files, nor any job's exports, use."""
    lowered = name.lower()
    if lowered in BATCH_FILES:
        raise ValueError(f"name {name!r} is a file the batch writes itself ({', '.join(BATCH_FILES)}); "
                         "choose another name")
    if lowered.endswith(EXPORT_SUFFIXES):
        raise ValueError(f"name {name!r} ends like a job's export ({', '.join(EXPORT_SUFFIXES)}), which another "
                         "job's bundle would collide with; choose another name")
    return name


def check_text(value: str, key: str) -> str:
    """Text that is Unicode: JSON's \\ud800 escape (a lone surrogate) decodes to a string no encoder takes."""
    try:
        value.encode("utf-8")
    except UnicodeEncodeError as exc:
        raise ValueError(f"{key} is not Unicode text: character {exc.start + 1} is a lone surrogate "
                         f"(\\u{ord(value[exc.start]):04x}); JSON \\u escapes must come in valid pairs") from None
    return value


def check_seed(value: object) -> int:
    """A seed is an integer in 0..2**32-1 (what numpy's generators and llama.cpp take)."""
    if isinstance(value, bool) or not isinstance(value, int):
        raise ValueError(f"seed must be a whole number, got {value!r}")
    if not 0 <= value <= MAX_SEED:
        raise ValueError(f"seed must be between 0 and {MAX_SEED}, got {value}")
    return value


def check_simulate_seconds(value: object) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise ValueError(f"simulate must be a number of seconds, got {value!r}")
    seconds = float(value)
    if not math.isfinite(seconds) or not 0 < seconds <= MAX_SIMULATE_SECONDS:
        raise ValueError(f"simulate must be more than 0 and at most {MAX_SIMULATE_SECONDS:g} seconds, got {value!r}")
    return seconds


def _did_you_mean(key: str, choices: tuple[str, ...] = REQUIRED + OPTIONAL) -> str:
    close = difflib.get_close_matches(key, choices, n=1)
    return f" (did you mean {close[0]!r}?)" if close else ""


def check_exports(value: object, simulate: float | None) -> tuple[str, ...]:
    """`export` is a list of distinct format names; those that read the run need `simulate`."""
    if not isinstance(value, list) or not all(isinstance(kind, str) for kind in value):
        raise ValueError(f"export must be a list of format names like [\"rosbag\"], got {value!r}")
    unknown = [kind for kind in value if kind not in EXPORT_KINDS]
    if unknown:
        raise ValueError("; ".join(f"unknown export {kind!r}{_did_you_mean(kind, EXPORT_KINDS)} "
                                   f"(formats: {', '.join(EXPORT_KINDS)})" for kind in unknown))
    repeated = sorted({kind for kind in value if value.count(kind) > 1})
    if repeated:
        raise ValueError(f"export lists {', '.join(repeated)} more than once")
    needing = [kind for kind in value if kind in NEEDS_RUN]
    if needing and simulate is None:
        raise ValueError(f"export {', '.join(needing)} needs a simulated run: add \"simulate\": SECONDS")
    return tuple(value)


def check_followups(value: object) -> tuple[str, ...]:
    """`refine` is a list of follow-up sentences, each non-empty and as long as a prompt may be."""
    if not isinstance(value, list) or not all(isinstance(f, str) for f in value):
        raise ValueError(f"refine must be a list of follow-up sentences like [\"make the queue longer\"], got {value!r}")
    if len(value) > MAX_FOLLOWUPS:
        raise ValueError(f"refine lists {len(value)} follow-ups; at most {MAX_FOLLOWUPS}")
    for k, followup in enumerate(value):
        if not followup.strip():
            raise ValueError(f"refine[{k}] is empty")
        if len(followup) > MAX_PROMPT_CHARS:
            raise ValueError(f"refine[{k}] is {len(followup)} characters; the limit is {MAX_PROMPT_CHARS}")
    return tuple(value)


def _check_job(number: int, job: object, index: int) -> list[BatchJob]:
    if not isinstance(job, dict):
        raise ValueError("a job must be a JSON object like {\"world\": ..., \"preset\": ..., \"prompt\": ...}")
    unknown = [k for k in job if k not in REQUIRED + OPTIONAL]
    if unknown:
        raise ValueError("; ".join(f"unknown key {k!r}{_did_you_mean(str(k))}" for k in unknown))
    missing = [k for k in REQUIRED if k not in job]
    if missing:
        raise ValueError(f"missing {', '.join(missing)}")
    for key in REQUIRED:
        value = job[key]
        if not isinstance(value, str) or not value.strip():
            raise ValueError(f"{key} must be a non-empty string, got {value!r}")
        check_text(value, key)
    if len(job["prompt"]) > MAX_PROMPT_CHARS:
        raise ValueError(f"prompt is {len(job['prompt'])} characters; the limit is {MAX_PROMPT_CHARS}")
    seed = check_seed(job.get("seed", 0))
    simulate = job.get("simulate")
    # "simulate": true runs the scenario for its own length (long enough for its planned behaviours)
    seconds = SCENARIO_LENGTH if simulate is True else None if simulate in (None, 0, False) \
        else check_simulate_seconds(simulate)
    name = job.get("name")
    if name is not None and (not isinstance(name, str) or not name.strip()):
        raise ValueError(f"name must be a non-empty string, got {name!r}")
    exports = check_exports(job["export"], seconds) if "export" in job else ()
    folder = check_folder_name(folder_name(name if name is not None
                                           else f"{index:03d}-{Path(job['world']).stem}-{job['preset']}"))
    followups = check_followups(job["refine"]) if "refine" in job else ()
    plain = BatchJob(number, job["world"].strip(), job["preset"].strip(), job["prompt"], seed, folder, seconds, exports,
                     refine=followups)
    if "variations" not in job:
        return [plain]
    count = check_variations(job["variations"])
    return [replace(plain, seed=variation_seed(seed, i), name=folder + variation_suffix(i, count),
                    variation=Variation(i, count, seed)) for i in range(count)]


def read_jobs(path: str | Path) -> tuple[list[BatchJob], list[JobProblem]]:
    """The good jobs of a job file and the problems of the bad lines; JobFileError if none can be read."""
    source = Path(path)
    try:
        if not source.is_file():
            raise JobFileError(f"{source}: no such job file")
        if source.stat().st_size > MAX_JOB_FILE_BYTES:
            raise JobFileError(f"{source}: larger than {MAX_JOB_FILE_BYTES // 2**20} MB")
        text = source.read_bytes().decode("utf-8")
    except UnicodeDecodeError as exc:
        raise JobFileError(f"{source}: not UTF-8 text (byte {exc.start})") from None
    except OSError as exc:
        raise JobFileError(f"{source}: cannot read it: {exc.strerror}") from None
    jobs: list[BatchJob] = []
    problems: list[JobProblem] = []
    names: dict[str, int] = {}
    index = 0
    for number, line in enumerate(text.splitlines(), start=1):
        if not line.strip() or line.lstrip().startswith("#"):
            continue
        index += 1
        try:
            data = json.loads(line)
        except json.JSONDecodeError as exc:
            problems.append(JobProblem(number, f"not valid JSON: {exc.msg} (column {exc.colno})"))
            continue
        except ValueError:  # Python's own limit on the digits of an integer
            problems.append(JobProblem(number, "a number has more than 4,300 digits; no value of a job is that long"))
            continue
        except RecursionError:
            problems.append(JobProblem(number, "the JSON nests too deeply to be a job"))
            continue
        try:
            expanded = _check_job(number, data, index)
        except (ValueError, RecursionError) as exc:
            problems.append(JobProblem(number, str(exc) or "not a valid job"))
            continue
        clash = next(((job.name, names[job.name.lower()]) for job in expanded if job.name.lower() in names), None)
        if clash is not None:
            problems.append(JobProblem(number, f"name {clash[0]!r} is already used by line {clash[1]}; "
                                               "two jobs cannot write the same bundle"))
            continue
        for job in expanded:
            names[job.name.lower()] = number
        jobs.extend(expanded)
    if not jobs and not problems:
        raise JobFileError(f"{source}: no jobs (one JSON object per line)")
    return jobs, problems
