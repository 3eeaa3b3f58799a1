"""Presets: deterministic configuration overlays on the generation pipeline, stored as data.

A preset is a YAML file (shipped ones in `presets/`, user ones in `config_dir()/presets/`) that sets
the bt model's prompt template, which nodes retrieval may return and the model may use, how goals
are sampled, whether agents follow planned waypoints or a velocity field, the planner settings and
the population limits. The pipeline's architecture never changes with the preset; only these values.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Any

import yaml

from grove_tui.errors import GenerationError, PresetError, PromptError
from grove_tui.jsontypes import Parsed
from grove_tui.limits import MAX_GROUP_COUNT
from grove_tui.paths import presets_dir
from grove_tui.scenario.model import DEFAULT_AGENT_RADIUS, RADIUS_RANGE
from grove_tui.settings import config_dir


GOAL_SAMPLING = ("spread", "sequential", "exit")
# How each evacuee picks among the exits it may use: the nearest by walking distance, or the one it
# expects to be out of soonest, counting the people already heading there (RiMEA test 11).
EXIT_CHOICE = ("nearest", "least_congested")
VELOCITY = ("waypoints", "field")
CONTEXT = ("rois", "world")
REQUIRED_ROIS = ("exits",)


@dataclass(frozen=True)
class PlannerSettings:
    enabled: bool = True
    resolution: float = 0.1
    # The grid is shrunk by this much round walls so a centre on a free cell keeps the body off them:
    # the people's radius unless a preset sets planner.inflation.
    inflation: float = DEFAULT_AGENT_RADIUS


@dataclass(frozen=True)
class Limits:
    max_groups: int = 6
    max_count: int = 40
    max_depth: int = 3
    default_count: int = 4


@dataclass(frozen=True)
class Preset:
    name: str
    description: str
    template: str
    context: str  # "rois": only the selected RoIs go to the bt model; "world": the whole world (baseline)
    retrieval_filter: str | None  # the preset tag retrieval filters on; None retrieves nothing, every node is offered
    retrieval_k: int
    control_nodes: tuple[str, ...]
    allowed_nodes: tuple[str, ...]  # leaves the model may use; empty: whatever retrieval returns (minus forbidden)
    forbidden_nodes: tuple[str, ...]
    required_nodes: tuple[str, ...]  # leaves always offered, retrieved or not, so the preset's behavior is expressible
    goal_sampling: str
    velocity: str
    planner: PlannerSettings
    limits: Limits
    required_rois: tuple[str, ...]
    max_vel: float
    source: Path | None = None
    agent_radius: float = DEFAULT_AGENT_RADIUS  # every generated person's body radius (agent.radius)
    exit_choice: str = "nearest"  # EXIT_CHOICE: how evacuees pick among the exits they may use
    # Node documents always in the bt model's prompt, in this order, inside the system message whose KV
    # state is cached per world and preset (synthesis.py): the preset's everyday vocabulary, so most
    # sentences need no card of their own. Retrieval adds the others after them.
    pinned_documents: tuple[str, ...] = ()

    @property
    def guided(self) -> bool:
        return self.context == "rois"


def _user_presets_dir() -> Path:
    return config_dir() / "presets"


def list_presets() -> list[str]:
    """Shipped presets first (in a stable order), then the user's, without duplicates."""
    names: list[str] = []
    for folder in (presets_dir(), _user_presets_dir()):
        if folder.is_dir():
            for path in sorted(folder.glob("*.yaml")):
                if path.stem not in names:
                    names.append(path.stem)
    return names


def load_preset(name_or_path: str | Path) -> Preset:
    """A preset by name (user presets override shipped ones) or by path to a YAML file."""
    text = str(name_or_path).strip()
    if not text:
        raise PresetError("no preset given; choose one of: " + ", ".join(list_presets()))
    candidate = Path(text)
    if candidate.suffix in (".yaml", ".yml") or candidate.is_file():
        if not candidate.is_file():
            raise PresetError(f"{candidate}: no such preset file")
        return _load_file(candidate)
    for folder in (_user_presets_dir(), presets_dir()):
        path = folder / f"{text}.yaml"
        if path.is_file():
            return _load_file(path)
    raise PresetError(f"unknown preset {text!r}; known presets: " + ", ".join(list_presets()))


def _load_file(path: Path) -> Preset:
    try:
        data = yaml.safe_load(path.read_text(encoding="utf-8"))
    except yaml.YAMLError as exc:
        raise PresetError(f"{path}: not valid YAML: {exc}") from None
    return preset_from_dict(data, source=path)


def preset_from_dict(data: object, source: Path | None = None) -> Preset:
    where = str(source) if source else "<preset>"
    if not isinstance(data, dict):
        raise PresetError(f"{where}: expected a mapping at the top level")

    def need(key: str, kind: type | tuple[type, ...]) -> Any:  # Any: of `kind`, which the caller names
        if key not in data:
            raise PresetError(f"{where}: missing key {key!r}")
        value = data[key]
        if not isinstance(value, kind):
            raise PresetError(f"{where}: {key} must be {_kind_name(kind)}, got {value!r}")
        return value

    def choice(key: str, options: tuple[str, ...]) -> str:
        value = str(need(key, str))
        if value not in options:
            raise PresetError(f"{where}: {key} must be one of {', '.join(options)}, got {value!r}")
        return value

    name = need("name", str).strip()
    if not name:
        raise PresetError(f"{where}: name must not be empty")
    retrieval = data.get("retrieval") or {}
    nodes = data.get("nodes") or {}
    planner = data.get("planner") or {}
    limits = data.get("limits") or {}
    agent = data.get("agent") or {}
    for key, block in (("retrieval", retrieval), ("nodes", nodes), ("planner", planner), ("limits", limits), ("agent", agent)):
        if not isinstance(block, dict):
            raise PresetError(f"{where}: {key} must be a mapping")

    def names(block: Parsed, key: str, path: str) -> tuple[str, ...]:
        value = block.get(key) or []
        if not isinstance(value, list) or not all(isinstance(v, str) for v in value):
            raise PresetError(f"{where}: {path} must be a list of node names")
        return tuple(value)

    def positive(block: Parsed, key: str, path: str, default: float, kind: type = int) -> Any:  # Any: of `kind`
        value = block.get(key, default)
        if isinstance(value, bool) or not isinstance(value, (int, float)) or value <= 0:
            raise PresetError(f"{where}: {path} must be a positive number, got {value!r}")
        if kind is int and int(value) != value:
            raise PresetError(f"{where}: {path} must be a whole number, got {value!r}")
        return kind(value)

    retrieval_filter = retrieval.get("filter", name)
    if retrieval_filter is not None and not isinstance(retrieval_filter, str):
        raise PresetError(f"{where}: retrieval.filter must be a preset tag or null")
    k = retrieval.get("k", 8)
    if isinstance(k, bool) or not isinstance(k, int) or k < 0:
        raise PresetError(f"{where}: retrieval.k must be a whole number >= 0, got {k!r}")
    required = names(data, "required_rois", "required_rois")
    for item in required:
        if item not in REQUIRED_ROIS:
            raise PresetError(f"{where}: required_rois may hold {', '.join(REQUIRED_ROIS)}, got {item!r}")
    enabled = planner.get("enabled", True)
    if not isinstance(enabled, bool):
        raise PresetError(f"{where}: planner.enabled must be true or false")
    agent_radius = positive(agent, "radius", "agent.radius", DEFAULT_AGENT_RADIUS, float)
    if not RADIUS_RANGE[0] <= agent_radius <= RADIUS_RANGE[1]:
        raise PresetError(f"{where}: agent.radius must be {RADIUS_RANGE[0]}..{RADIUS_RANGE[1]} m, got {agent_radius!r}")
    exit_choice = data.get("exit_choice", "nearest")
    if exit_choice not in EXIT_CHOICE:
        raise PresetError(f"{where}: exit_choice must be one of {', '.join(EXIT_CHOICE)}, got {exit_choice!r}")
    control = names(nodes, "control", "nodes.control")
    if not control:
        raise PresetError(f"{where}: nodes.control must name at least one control node")
    return Preset(
        name=name,
        description=need("description", str).strip().splitlines()[0] if need("description", str).strip() else "",
        template=need("template", str).strip(),
        context=choice("context", CONTEXT) if "context" in data else "rois",
        retrieval_filter=retrieval_filter,
        retrieval_k=k,
        control_nodes=control,
        allowed_nodes=names(nodes, "allowed", "nodes.allowed"),
        forbidden_nodes=names(nodes, "forbidden", "nodes.forbidden"),
        required_nodes=names(nodes, "required", "nodes.required"),
        goal_sampling=choice("goal_sampling", GOAL_SAMPLING),
        velocity=choice("velocity", VELOCITY),
        planner=PlannerSettings(
            enabled=enabled,
            resolution=positive(planner, "resolution", "planner.resolution", 0.1, float),
            inflation=positive(planner, "inflation", "planner.inflation", agent_radius, float),
        ),
        limits=Limits(
            max_groups=positive(limits, "max_groups", "limits.max_groups", 6),
            max_count=_at_most(positive(limits, "max_count", "limits.max_count", 40), MAX_GROUP_COUNT,
                               f"{where}: limits.max_count"),
            max_depth=positive(limits, "max_depth", "limits.max_depth", 3),
            default_count=positive(limits, "default_count", "limits.default_count", 4),
        ),
        required_rois=required,
        max_vel=positive(agent, "max_vel", "agent.max_vel", 1.0, float),
        source=source,
        agent_radius=agent_radius,
        exit_choice=exit_choice,
        pinned_documents=names(retrieval, "pinned", "retrieval.pinned"),
    )


def _kind_name(kind: type | tuple[type, ...]) -> str:
    kinds = kind if isinstance(kind, tuple) else (kind,)
    return " or ".join({str: "text", int: "a whole number", float: "a number", dict: "a mapping", list: "a list", bool: "true or false"}.get(k, k.__name__) for k in kinds)


def _at_most(value: int, most: int, what: str) -> int:
    if value > most:
        raise PresetError(f"{what}: {value} is over the limit of {most} people per group (grove_tui/limits.py)")
    return value
