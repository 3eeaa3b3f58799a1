"""Strategic layer: which regions of interest (RoIs) of the world the scenario is about.

The places are the reading's (language/): every place the sentence names, in reading order, each a
zone, door or entity of the world, and, where the reader is unsure between places ("the restroom":
the men's or the women's), the places it weighed. This module adds what the preset needs (every exit
under the emergency preset), the zones that contain the places, and, when the sentence names no place,
the best-connected zones; it summarises them for the behavior-tree model. A place the sentence names
in a place role that the world does not have is refused here, with the closest names. With a roi
model, each unsure choice is put to the model, which may only pick among the places weighed.
"""

from __future__ import annotations

import difflib
import json
import threading
from collections.abc import Sequence
from dataclasses import dataclass, field, replace
from typing import TypeVar

from grove_tui.errors import PromptError
from grove_tui.generation.picked_places import model_pick
from grove_tui.generation.presets import Preset
from grove_tui.language.model import FieldConfidence, GroupReading, PromptReading, RobotReading
from grove_tui.llm.grammar import schema_to_gbnf
from grove_tui.llm.local import LocalLLM
from grove_tui.world.model import World

PLACE_FIELDS = ("start", "destination", "location", "via")


@dataclass(frozen=True)
class RoIMatch:
    kind: str  # "zone" | "door" | "entity"
    name: str
    zone: str
    score: float  # how sure the reading is of it (1.0: named outright); 0 for places added by a rule
    matched: tuple[str, ...]  # the reading's fields it fills ("0.destination", "robot.via"); empty when added by a rule
    reason: str  # "prompt" (the sentence names it) | "alternative" | "preset" | "container" | "default" | "model" | "world"


@dataclass(frozen=True)
class Ambiguity:
    """A place field the reader is unsure of, and the places it weighed (the chosen one first)."""

    group: int | None  # index of the reading's group; None for the robot
    field: str  # "start", "destination", "location" or "via"
    options: tuple[str, ...]
    reason: str = ""


@dataclass
class RoISelection:
    """What the strategic layer hands on: selected RoIs, their zones, and the text the bt model sees."""

    matches: list[RoIMatch]
    zones: list[str]  # selected zone names, in prompt order
    named_zones: list[str]  # zones the sentence itself names (directly or through a door/entity), for grounding
    summary: str  # compact description of the selected RoIs for the bt model
    roi_names: list[str] = field(default_factory=list)  # every name the draft may use as a target
    exits: list[str] = field(default_factory=list)  # exit door names offered to the model
    ambiguous: list[Ambiguity] = field(default_factory=list)  # unsure choices a roi model may settle

    @property
    def names(self) -> list[str]:
        return [m.name for m in self.matches]


def close_matches(world: World, phrase: str, n: int = 5) -> list[str]:
    """The world's places whose names or aliases look most like `phrase` (for a refusal's hint)."""
    label: dict[str, str] = {}
    for place in world.roi_index():
        label.setdefault(place.name.replace("_", " "), place.name)
        for alias in place.aliases:
            label.setdefault(alias.lower(), place.name)
    hits = difflib.get_close_matches(phrase.lower(), list(label), n=n * 2, cutoff=0.4)
    out = list(dict.fromkeys(label[h] for h in hits))
    if len(out) < n:
        out += [z.name for z in world.zones if z.name not in out]  # what exists, always
    return out[:n]


def _fields_of(reading: PromptReading) -> dict[str, list[str]]:
    """Place name -> the reading's fields it fills ("0.destination", "robot.via")."""
    fields: dict[str, list[str]] = {}
    subjects: list[tuple[str, GroupReading | RobotReading]] = [(str(i), g) for i, g in enumerate(reading.groups)]
    if reading.robot is not None:
        subjects.append(("robot", reading.robot))
    for key, subject in subjects:
        for role in ("start", "location", "via", "destination"):
            value = getattr(subject, role)
            for name in (value if isinstance(value, tuple) else (value,)):
                if name:
                    fields.setdefault(name, []).append(f"{key}.{role}")
    return fields


def reading_places(reading: PromptReading) -> list[str]:
    """Every place the reading names: those it gives a role first (group by group, then the robot's),
    then the rest of the sentence's, in reading order."""
    return list(dict.fromkeys([*_fields_of(reading), *reading.places]))


def ambiguities(reading: PromptReading) -> list[Ambiguity]:
    """The place fields the reader is unsure of, with the places it weighed."""
    out: list[Ambiguity] = []
    for index, conf in reading.unsure():
        subject: GroupReading | RobotReading | None = reading.robot if index is None else reading.groups[index]
        if subject is None or conf.field not in PLACE_FIELDS or not conf.alternatives:
            continue
        value = getattr(subject, conf.field)
        chosen = [v for v in (value if isinstance(value, tuple) else (value,)) if v]
        if chosen:
            out.append(Ambiguity(index, conf.field, tuple(dict.fromkeys([chosen[0], *conf.alternatives])),
                                 conf.reason))
    return out


def _any_exit_will_do(world: World, reading: PromptReading, ambiguity: Ambiguity) -> bool:
    """Evacuees unsure of which exit ("the nearest exit", weighed against exits and doors named "..._exit"):
    the evacuation sends each person to the exit nearest to them, so a model's pick of one would be a promise the run does not keep. The field
    stays unsure, and the grounding report accepts any exit the reader weighed."""
    if ambiguity.group is None or ambiguity.field != "destination":
        return False
    exits = {d.name for d in world.exits()}
    return reading.groups[ambiguity.group].intent == "evacuate" and bool(exits & set(ambiguity.options))


def _match(world: World, name: str, score: float, matched: Sequence[str], reason: str) -> RoIMatch:
    place = world.find(name)
    kind = "zone" if hasattr(place, "entities") else "door" if hasattr(place, "leads_to") else "entity"
    zone = place.name if kind == "zone" else str(getattr(place, "zone"))
    return RoIMatch(kind, name, zone, score, tuple(matched), reason)


def select_rois(world: World, preset: Preset, reading: PromptReading, max_default_zones: int = 3) -> RoISelection:
    """The strategic layer: the places the reading names plus what the preset needs, summarised.

    Only the reading's unknown places (noun phrases in a place role the world lacks) are refused."""
    if reading.unknown_places:
        parts = [f"'{p}' (closest: {', '.join(close_matches(world, p))})" for p in reading.unknown_places]
        raise PromptError(f"the prompt names a place world '{world.name}' does not have: " + "; ".join(parts))
    fields = _fields_of(reading)
    unsure = {f"{'robot' if i is None else i}.{c.field}": c.score for i, c in reading.unsure()}
    matches = [_match(world, name, min((unsure.get(f, 1.0) for f in fields.get(name, ())), default=1.0),
                      fields.get(name, ()), "prompt") for name in reading_places(reading)]
    ambiguous = [a for a in ambiguities(reading) if not _any_exit_will_do(world, reading, a)]
    have = {m.name for m in matches}
    for ambiguity in ambiguous:
        for name in ambiguity.options:
            if name not in have:
                matches.append(_match(world, name, 0.0, (), "alternative"))
                have.add(name)
    if preset.context == "world":
        return _whole_world(world, matches, ambiguous)
    named_zones = list(dict.fromkeys(m.zone for m in matches if m.reason == "prompt"))
    if not matches:
        # Nothing named: the busiest hubs (most doors) make a plausible default stage.
        hubs = sorted(world.zones, key=lambda z: (-len(world.doors_of(z.name)), -z.area, z.name))[:max_default_zones]
        matches = [RoIMatch("zone", z.name, z.name, 0.0, (), "default") for z in hubs]
    return _selection(world, preset, matches, named_zones, ambiguous)


def _selection(world: World, preset: Preset, matches: list[RoIMatch], named_zones: list[str],
               ambiguous: list[Ambiguity]) -> RoISelection:
    selected = {m.name for m in matches}
    for m in list(matches):
        if m.kind != "zone" and m.zone not in selected:
            matches.append(RoIMatch("zone", m.zone, m.zone, 0.0, (), "container"))
            selected.add(m.zone)
    exits: list[str] = []
    if "exits" in preset.required_rois:
        for door in world.exits():
            exits.append(door.name)
            if door.name not in selected:
                matches.append(RoIMatch("door", door.name, door.zone, 0.0, (), "preset"))
                selected.add(door.name)
    zones = list(dict.fromkeys(m.zone if m.kind != "zone" else m.name for m in matches
                               if m.kind == "zone" or m.reason != "preset"))
    roi_names = list(dict.fromkeys(m.name for m in matches))
    summary = summarize(world, zones, {m.name for m in matches}, exits)
    return RoISelection(matches, zones, named_zones or zones, summary, roi_names, exits, ambiguous)


def _whole_world(world: World, named: list[RoIMatch], ambiguous: list[Ambiguity]) -> RoISelection:
    zones = [z.name for z in world.zones]
    everything = []
    for z in world.zones:
        everything.append(RoIMatch("zone", z.name, z.name, 0.0, (), "world"))
        everything += [RoIMatch("door", d.name, z.name, 0.0, (), "world") for d in z.doors]
        everything += [RoIMatch("entity", e.name, z.name, 0.0, (), "world") for e in z.entities]
    exits = [d.name for d in world.exits()]
    names = [m.name for m in everything]
    named_zones = list(dict.fromkeys(m.zone for m in named if m.reason == "prompt")) or zones
    return RoISelection(everything, zones, named_zones, summarize(world, zones, set(names), exits, full=True), names,
                        exits, ambiguous)


def _fmt(v: float) -> str:
    return f"{v:.1f}".rstrip("0").rstrip(".") if abs(v - round(v)) > 1e-9 else str(int(round(v)))


def _pt(p: Sequence[float]) -> str:
    return f"({_fmt(p[0])},{_fmt(p[1])})"


def summarize(world: World, zones: Sequence[str], selected: set[str], exits: Sequence[str], full: bool = False) -> str:
    """The selected places as the bt model reads them.

    Guided presets get one line per selected zone naming exactly the places the draft may use there
    (its selected doors and entities), then the exits: no coordinates, boundaries or descriptions,
    because the model writes names only and post-processing resolves them to points (issue 20: the
    long form cost ~100 tokens per zone of prefill). `full` (the vanilla baseline) lists the whole
    zone with boundary, door positions, tags and descriptions, as the paper's baseline does.
    """
    if not full:
        return _compact_summary(world, zones, selected, exits)
    lines: list[str] = []
    for name in zones:
        z = world.zone(name)
        head = f"zone {z.name} ({z.type})"
        if z.aliases:
            head += " aka " + ", ".join(z.aliases)
        lines.append(f"{head}: {z.description}".rstrip(": ") if z.description else head)
        lines.append("  boundary: " + " ".join(_pt(p) for p in z.boundary))
        if z.tags:
            lines.append("  tags: " + ", ".join(z.tags))
        doors = [d for d in world.doors() if d.zone == z.name or d.leads_to == z.name]
        if doors:
            parts = []
            for d in doors:
                other = d.leads_to if d.zone == z.name else d.zone
                parts.append(f"{d.name} {_pt(d.position)} to {other}" + (" EXIT" if d.exit else ""))
            lines.append("  doors: " + "; ".join(parts))
        ents = list(z.entities)
        if ents:
            parts = []
            for e in ents:
                text = f"{e.name} ({e.type}) at {_pt(e.interaction_point)}"
                if e.description:
                    text += f" - {e.description}"
                parts.append(text)
            lines.append("  entities: " + "; ".join(parts))
    if exits:
        exit_doors = [d for d in world.exits() if d.name in exits]
        lines.append("exits: " + "; ".join(f"{d.name} {_pt(d.position)} in {d.zone}" for d in exit_doors))
    return "\n".join(lines)


def _compact_summary(world: World, zones: Sequence[str], selected: set[str], exits: Sequence[str]) -> str:
    """`- pharmacy (pharmacy): pharmacy_counter (counter), pharmacy_door (door to main_corridor)` per zone."""
    lines: list[str] = []
    shown: set[str] = set()
    for name in zones:
        z = world.zone(name)
        places = [f"{e.name} ({e.type})" for e in z.entities if e.name in selected]
        shown |= {e.name for e in z.entities if e.name in selected}
        for d in world.doors():
            if d.name in selected and d.name not in shown and (d.zone == z.name or d.leads_to == z.name):
                other = d.leads_to if d.zone == z.name else d.zone
                places.append(f"{d.name} ({'exit' if d.exit else 'door to ' + other})")
                shown.add(d.name)
        lines.append(f"- {z.name} ({z.type})" + (": " + ", ".join(places) if places else ""))
    rest = [d for d in world.exits() if d.name in exits and d.name not in shown]
    if rest:
        lines.append("- exits: " + ", ".join(f"{d.name} (in {d.zone})" for d in rest))
    return "\n".join(lines)


def describe_selection(selection: RoISelection) -> list[dict[str, object]]:
    """JSON-ready record of the selection for generation.json."""
    return [{"kind": m.kind, "name": m.name, "zone": m.zone, "score": m.score, "matched": list(m.matched),
             "reason": m.reason} for m in selection.matches]



def refine_with_model(world: World, preset: Preset, reading: PromptReading, selection: RoISelection,
                      llm: LocalLLM, seed: int = 0,
                      cancel: threading.Event | None = None) -> tuple[RoISelection, PromptReading, int, int]:
    """Let the roi model settle each place the reader is unsure of, under a grammar that only allows
    the places it weighed. Returns the selection without the places not chosen, the reading with the
    model's choices (each a sure field now, its reason saying the model chose), and the prompt and
    completion tokens spent. Places the reader is sure of are never touched."""
    prompt_tokens = completion_tokens = 0
    dropped: set[str] = set()
    chosen: dict[tuple[int | None, str], tuple[str, str]] = {}  # (group, field) -> (old, new)
    for ambiguity in selection.ambiguous:
        names = list(ambiguity.options)
        lines = []
        for name in names:
            aliases = ", ".join(getattr(world.find(name), "aliases", ()) or ())
            lines.append(f"- {name}" + (f" ({aliases})" if aliases else ""))
        messages = [
            {"role": "system", "content": "You choose which place a sentence means. Answer with JSON only."},
            {"role": "user", "content": f"Sentence: {reading.prompt}\n{ambiguity.reason}. It could mean:\n"
                                        + "\n".join(lines) + '\nAnswer {"place": NAME}.'},
        ]
        schema = {"type": "object", "properties": {"place": {"enum": names}}, "required": ["place"],
                  "additionalProperties": False}
        generation = llm.generate(messages, grammar=schema_to_gbnf(schema), max_tokens=32, seed=seed, cancel=cancel)
        prompt_tokens += generation.prompt_tokens
        completion_tokens += generation.completion_tokens
        try:
            choice = json.loads(generation.text)["place"]
        except (ValueError, KeyError, TypeError):
            continue  # the grammar makes this unreachable; keeping every candidate is the safe answer
        if choice in names:
            dropped |= set(names) - {choice}
            chosen[(ambiguity.group, ambiguity.field)] = (names[0], choice)
    if not chosen:
        return selection, reading, prompt_tokens, completion_tokens
    reading = _with_choices(reading, chosen)
    still_named = set(reading_places(reading))
    kept = [m for m in selection.matches if m.name not in dropped or m.name in still_named]
    # A zone that was only there to contain a dropped door or entity goes too.
    kept = [m for m in kept if m.reason != "container" or any(k.zone == m.name and k.kind != "zone" for k in kept)]
    zones = list(dict.fromkeys(m.zone for m in kept if m.reason != "preset"))
    named = [z for z in selection.named_zones if z in zones]
    summary = summarize(world, zones, {m.name for m in kept}, selection.exits)
    refined = RoISelection(kept, zones, named or zones, summary, [m.name for m in kept], selection.exits,
                           [a for a in selection.ambiguous if (a.group, a.field) not in chosen])
    return refined, reading, prompt_tokens, completion_tokens


def _with_choices(reading: PromptReading, chosen: dict[tuple[int | None, str], tuple[str, str]]) -> PromptReading:
    groups = list(reading.groups)
    robot = reading.robot
    for (group, name), (old, new) in chosen.items():
        if group is None and robot is not None:
            robot = _set_place(robot, name, old, new)
        elif group is not None:
            groups[group] = _set_place(groups[group], name, old, new)
    return replace(reading, groups=tuple(groups), robot=robot)


Subject = TypeVar("Subject", GroupReading, RobotReading)


def _set_place(subject: Subject, name: str, old: str, new: str) -> Subject:
    """The subject with its place field `name` set to `new` (in place of `old`), and sure of it."""
    # the model's pick is what the scenario uses, but the places it chose among still fit (picked_places.py)
    confidence = tuple(c if c.field != name else model_pick(c, new, old) for c in subject.confidence)
    if name == "via":
        return replace(subject, via=tuple(new if v == old else v for v in subject.via), confidence=confidence)
    if name == "start":
        return replace(subject, start=new, confidence=confidence)
    if name == "destination":
        return replace(subject, destination=new, confidence=confidence)
    return replace(subject, location=new, confidence=confidence)
