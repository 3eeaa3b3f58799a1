"""Reading a world YAML: every problem at once, each with file, YAML path and line.

Worlds are written by hand, so loading validates everything it can and reports *all* problems,
each naming the file, the YAML path (``zones[3].doors[1].width``) and the line.
"""

from __future__ import annotations

import difflib
import hashlib
import math
import os
import re
from dataclasses import dataclass, field
from functools import cached_property
from pathlib import Path
from collections.abc import Sequence

import numpy as np
from numpy.typing import NDArray
import shapely
import shapely.ops
import yaml
from shapely.geometry import LineString, Point, Polygon
from shapely.geometry.base import BaseGeometry
from shapely.ops import unary_union
from shapely.validation import explain_validity

from grove_tui.limits import MAX_COORDINATE as LIMIT_COORDINATE
from grove_tui.limits import InputLimitError, YamlPath, check_regular_file, compose_yaml, read_text_bounded
from grove_tui.paths import worlds_dir

from grove_tui.world.model import (OUTSIDE, ON_BOUNDARY_TOLERANCE, OVERLAP_AREA_TOLERANCE, DOOR_CLEARANCE, SNAKE_CASE, WorldProblem, WorldError, Door, Entity, Obstacle, Zone, World, _unknown_name_message, Point2)


# --------------------------------------------------------------------------------------------
# YAML with line numbers


def format_path(path: YamlPath) -> str:
    text = ""
    for part in path:
        if isinstance(part, int):
            text += f"[{part}]"
        else:
            text += f".{part}" if text else str(part)
    return text or "(document)"


# Limits checked before anything is built, so a hostile or mistaken file fails fast with one
# message instead of hanging or exhausting memory (YAML size, depth and alias limits are in
# grove_tui.limits). A world of 20,000 zones is about 4 MB of YAML and loads in about 8 s.
MAX_WORLD_FILE_BYTES = 32 * 1024 * 1024
MAX_ZONES = 30_000
# Coordinates and sizes in metres: the range a scenario can use (limits.MAX_COORDINATE, the bound of
# the behavior-tree ports that carry points), so `worlds check` refuses what generation could not use.
MAX_COORDINATE = LIMIT_COORDINATE
# Points of one polygon (zone boundary, footprint): a hand-drawn room has tens; a curved hall a few
# hundred. GEOS simplifies wall lines recursively, and a zigzag of some 80,000 points overflowed the
# C stack (exit 139) in `generate` after `worlds check` had passed it.
MAX_POLYGON_POINTS = 10_000
# The occupancy grid at the default 0.1 m resolution must stay under this many cells (it is built
# before planning and every planner map is a multiple of it): 250,000 m^2 of bounding box.
MAX_GRID_CELLS = 25_000_000
DEFAULT_GRID_RESOLUTION = 0.1


class _Problems:
    def __init__(self, file: str, lines: dict[YamlPath, int]) -> None:
        self.file = file
        self.lines = lines
        self.items: list[WorldProblem] = []

    def line_of(self, path: YamlPath) -> int | None:
        for cut in range(len(path), -1, -1):
            if path[:cut] in self.lines:
                return self.lines[path[:cut]]
        return None

    def add(self, path: YamlPath, message: str) -> None:
        self.items.append(WorldProblem(self.file, format_path(path), self.line_of(path), message))


# --------------------------------------------------------------------------------------------
# Field readers: each returns None (and records a problem) when the value is unusable.


def _is_number(value: object) -> bool:
    """A finite number within +-MAX_COORDINATE (huge ints would overflow float conversion)."""
    if not isinstance(value, (int, float)) or isinstance(value, bool):
        return False
    if isinstance(value, int):
        return -MAX_COORDINATE <= value <= MAX_COORDINATE
    return math.isfinite(value) and -MAX_COORDINATE <= value <= MAX_COORDINATE


def _short_repr(value: object, limit: int = 60) -> str:
    """repr() cut to `limit` characters: a message quoting a 5,000-digit number helps nobody
    (and repr of such an int raises ValueError)."""
    try:
        text = repr(value)
    except ValueError:
        text = f"<{type(value).__name__} too large to print>"
    return text if len(text) <= limit else text[:limit - 3] + "..."


# A key worth quoting back: a word or two. Anything else is quoted by position only, so a file that is
# not a world at all (a password file given by mistake, or through a link) is never echoed into a message.
_KEY_LIKE = re.compile(r"^[A-Za-z_][A-Za-z0-9_ -]{0,39}$")


def _check_keys(data: dict, allowed: tuple[str, ...], path: YamlPath, problems: _Problems) -> None:
    for key in data:
        if key not in allowed:
            if not (isinstance(key, str) and _KEY_LIKE.match(key)):
                problems.add(path, f"a key that is not a word (not one of {', '.join(allowed)})")
                continue
            close = difflib.get_close_matches(str(key), allowed, n=1)
            hint = f" (did you mean {close[0]!r}?)" if close else ""
            problems.add(path + (str(key),), f"unknown key {key!r}{hint}; allowed keys: {', '.join(allowed)}")


def _read_str(data: dict, key: str, path: YamlPath, problems: _Problems, required: bool = True,
              default: str = "") -> str | None:
    if key not in data or data[key] is None:
        if required:
            problems.add(path, f"missing required key {key!r}")
            return None
        return default
    value = data[key]
    if not isinstance(value, str) or not value.strip():
        problems.add(path + (key,), f"{key} must be a non-empty string, got {_short_repr(value)}")
        return None
    return value.strip()


def _read_name(data: dict, path: YamlPath, problems: _Problems) -> str | None:
    name = _read_str(data, "name", path, problems)
    if name is not None and not SNAKE_CASE.match(name):
        problems.add(path + ("name",), f"name {name!r} must be snake_case (lowercase letters, digits, underscores)")
    return name


def _read_str_list(data: dict, key: str, path: YamlPath, problems: _Problems) -> tuple[str, ...]:
    value = data.get(key)
    if value is None:
        return ()
    if not isinstance(value, list):
        problems.add(path + (key,), f"{key} must be a list of strings, got {type(value).__name__}")
        return ()
    items: list[str] = []
    for index, item in enumerate(value):
        if not isinstance(item, str) or not item.strip():
            problems.add(path + (key, index), f"{key} entries must be non-empty strings, got {_short_repr(item)}")
        else:
            items.append(item.strip())
    return tuple(items)


def _read_point(value: object, path: YamlPath, problems: _Problems, what: str) -> Point2 | None:
    if (not isinstance(value, list) or len(value) != 2 or not all(_is_number(v) for v in value)):
        problems.add(path, f"{what} must be a point [x, y] of two numbers within +-{MAX_COORDINATE:g} m, "
                           f"got {_short_repr(value)}")
        return None
    return (float(value[0]), float(value[1]))


def _read_polygon(data: dict, key: str, path: YamlPath, problems: _Problems) -> tuple[Point2, ...] | None:
    if key not in data:
        problems.add(path, f"missing required key {key!r} (a polygon: a list of [x, y] points)")
        return None
    value = data[key]
    if not isinstance(value, list) or len(value) < 3:
        problems.add(path + (key,), f"{key} must be a list of at least 3 [x, y] points, got {_short_repr(value)}")
        return None
    if len(value) > MAX_POLYGON_POINTS:
        problems.add(path + (key,), f"{key} has {len(value):,} points; at most {MAX_POLYGON_POINTS:,} per polygon "
                                    "are supported (simplify the outline)")
        return None
    points: list[Point2] = []
    for index, item in enumerate(value):
        point = _read_point(item, path + (key, index), problems, f"{key} point {index}")
        if point is None:
            return None
        points.append(point)
    if len(points) > 3 and points[0] == points[-1]:
        points.pop()
    polygon = Polygon(points)
    if not polygon.is_valid:
        reason = explain_validity(polygon)
        problems.add(path + (key,), f"{key} polygon is self-intersecting or otherwise invalid: {reason}")
        return None
    if polygon.area <= OVERLAP_AREA_TOLERANCE:
        problems.add(path + (key,), f"{key} polygon has no area (points are collinear or repeated)")
        return None
    return tuple(points)


def _read_positive(data: dict, key: str, path: YamlPath, problems: _Problems) -> float | None:
    if key not in data:
        problems.add(path, f"missing required key {key!r}")
        return None
    value = data[key]
    if not _is_number(value):
        problems.add(path + (key,), f"{key} must be a number in metres within +-{MAX_COORDINATE:g}, got {_short_repr(value)}")
        return None
    if value <= 0:
        problems.add(path + (key,), f"{key} must be positive, got {_short_repr(value)}")
        return None
    return float(value)


def _read_list(data: dict, key: str, path: YamlPath, problems: _Problems) -> list:
    value = data.get(key)
    if value is None:
        return []
    if not isinstance(value, list):
        problems.add(path + (key,), f"{key} must be a list, got {type(value).__name__}")
        return []
    return value


# --------------------------------------------------------------------------------------------
# Parsing and validation


ZONE_KEYS = ("name", "type", "description", "aliases", "tags", "boundary", "doors", "entities")
DOOR_KEYS = ("name", "position", "width", "leads_to", "exit", "description", "aliases", "tags")
ENTITY_KEYS = ("name", "type", "footprint", "interaction_point", "tags", "description", "aliases")
OBSTACLE_KEYS = ("name", "type", "footprint", "description")
WORLD_KEYS = ("name", "description", "zones", "obstacles")


@dataclass
class _DraftDoor:
    path: YamlPath
    name: str | None
    zone: str
    position: Point2 | None
    width: float | None
    leads_to: str | None
    exit: bool
    description: str
    aliases: tuple[str, ...]
    tags: tuple[str, ...]


@dataclass
class _DraftEntity:
    path: YamlPath
    name: str | None
    zone: str
    type: str | None
    footprint: tuple[Point2, ...] | None
    interaction_point: Point2 | None
    tags: tuple[str, ...]
    description: str
    aliases: tuple[str, ...]

    @cached_property
    def polygon(self) -> Polygon | None:
        return Polygon(self.footprint) if self.footprint else None


@dataclass
class _DraftZone:
    path: YamlPath
    name: str | None
    type: str | None
    description: str
    aliases: tuple[str, ...]
    tags: tuple[str, ...]
    boundary: tuple[Point2, ...] | None
    doors: list[_DraftDoor] = field(default_factory=list)
    entities: list[_DraftEntity] = field(default_factory=list)

    @cached_property
    def polygon(self) -> Polygon | None:
        return Polygon(self.boundary) if self.boundary else None


@dataclass
class _DraftObstacle:
    path: YamlPath
    name: str | None
    type: str
    description: str
    footprint: tuple[Point2, ...] | None

    @cached_property
    def polygon(self) -> Polygon | None:
        return Polygon(self.footprint) if self.footprint else None


def _read_door(data: object, path: YamlPath, zone_name: str, problems: _Problems) -> _DraftDoor | None:
    if not isinstance(data, dict):
        problems.add(path, f"a door must be a mapping with name, position, width, leads_to; got {_short_repr(data)}")
        return None
    _check_keys(data, DOOR_KEYS, path, problems)
    name = _read_name(data, path, problems)
    position = _read_point(data["position"], path + ("position",), problems, "position") if "position" in data else None
    if "position" not in data:
        problems.add(path, "missing required key 'position' (the door centre [x, y] on the zone boundary)")
    width = _read_positive(data, "width", path, problems)
    leads_to = _read_str(data, "leads_to", path, problems)
    exit_value = data.get("exit", leads_to == OUTSIDE)
    if not isinstance(exit_value, bool):
        problems.add(path + ("exit",), f"exit must be true or false, got {_short_repr(exit_value)}")
        exit_value = False
    return _DraftDoor(path, name, zone_name, position, width, leads_to, exit_value,
                      _read_str(data, "description", path, problems, required=False) or "",
                      _read_str_list(data, "aliases", path, problems), _read_str_list(data, "tags", path, problems))


def _read_entity(data: object, path: YamlPath, zone_name: str, problems: _Problems) -> _DraftEntity | None:
    if not isinstance(data, dict):
        problems.add(path, f"an entity must be a mapping with name, type, footprint, interaction_point; got {_short_repr(data)}")
        return None
    _check_keys(data, ENTITY_KEYS, path, problems)
    name = _read_name(data, path, problems)
    entity_type = _read_str(data, "type", path, problems)
    footprint = _read_polygon(data, "footprint", path, problems)
    if "interaction_point" in data:
        point = _read_point(data["interaction_point"], path + ("interaction_point",), problems, "interaction_point")
    else:
        problems.add(path, "missing required key 'interaction_point' (where a person stands to use it)")
        point = None
    return _DraftEntity(path, name, zone_name, entity_type, footprint, point,
                        _read_str_list(data, "tags", path, problems),
                        _read_str(data, "description", path, problems, required=False) or "",
                        _read_str_list(data, "aliases", path, problems))


def _read_zone(data: object, path: YamlPath, problems: _Problems) -> _DraftZone | None:
    if not isinstance(data, dict):
        problems.add(path, f"a zone must be a mapping with name, type, boundary; got {_short_repr(data)}")
        return None
    _check_keys(data, ZONE_KEYS, path, problems)
    name = _read_name(data, path, problems)
    zone = _DraftZone(path, name, _read_str(data, "type", path, problems),
                      _read_str(data, "description", path, problems, required=False) or "",
                      _read_str_list(data, "aliases", path, problems), _read_str_list(data, "tags", path, problems),
                      _read_polygon(data, "boundary", path, problems))
    zone_label = name or f"zones[{path[-1]}]"
    for index, item in enumerate(_read_list(data, "doors", path, problems)):
        door = _read_door(item, path + ("doors", index), zone_label, problems)
        if door is not None:
            zone.doors.append(door)
    for index, item in enumerate(_read_list(data, "entities", path, problems)):
        entity = _read_entity(item, path + ("entities", index), zone_label, problems)
        if entity is not None:
            zone.entities.append(entity)
    return zone


def _read_obstacle(data: object, path: YamlPath, problems: _Problems) -> _DraftObstacle | None:
    if not isinstance(data, dict):
        problems.add(path, f"an obstacle must be a mapping with name and footprint; got {_short_repr(data)}")
        return None
    _check_keys(data, OBSTACLE_KEYS, path, problems)
    return _DraftObstacle(path, _read_name(data, path, problems),
                          _read_str(data, "type", path, problems, required=False, default="obstacle") or "obstacle",
                          _read_str(data, "description", path, problems, required=False) or "",
                          _read_polygon(data, "footprint", path, problems))


def _door_geometry(door: _DraftDoor, polygon: Polygon) -> tuple[Point2, Point2]:
    """Unit vector along the nearest boundary edge and the unit normal pointing into the polygon."""
    px, py = door.position  # type: ignore[misc]
    coords = list(polygon.exterior.coords)
    best: tuple[float, Point2] | None = None
    for (x1, y1), (x2, y2) in zip(coords, coords[1:]):
        length = math.hypot(x2 - x1, y2 - y1)
        if length == 0:
            continue
        distance = LineString([(x1, y1), (x2, y2)]).distance(Point(px, py))
        if best is None or distance < best[0]:
            best = (distance, ((x2 - x1) / length, (y2 - y1) / length))
    assert best is not None
    ax, ay = best[1]
    normal = (-ay, ax)
    probe = Point(px + 0.01 * normal[0], py + 0.01 * normal[1])
    if not polygon.contains(probe):
        normal = (ay, -ax)
    return (ax, ay), normal


def _lies_on(opening: LineString, polygon: Polygon) -> bool:
    """True when the whole door opening runs along the polygon's boundary (not across a corner)."""
    samples = shapely.line_interpolate_point(opening, np.linspace(0.0, 1.0, 9), normalized=True)
    return bool((shapely.distance(polygon.exterior, samples) <= ON_BOUNDARY_TOLERANCE).all())


def _covers_with_tolerance(container: BaseGeometry, shape: Polygon) -> bool:
    # Exact predicates first; hand-typed coordinates on a shared edge can be off by rounding.
    return bool(container.covers(shape) or shape.difference(container).area <= OVERLAP_AREA_TOLERANCE)


def _opening(position: Point2, width: float, along: Point2) -> LineString:
    half = width / 2.0
    return LineString([(position[0] - half * along[0], position[1] - half * along[1]),
                       (position[0] + half * along[0], position[1] + half * along[1])])


def _check_extent(zones: list[_DraftZone], problems: _Problems) -> None:
    """The bounding box must rasterise to a grid of at most MAX_GRID_CELLS at the default resolution,
    or `generate` would try to allocate gigabytes after `worlds check` passed."""
    boundaries = [zone.boundary for zone in zones if zone.boundary]
    if not boundaries:
        return
    points = np.concatenate([np.asarray(boundary, dtype=np.float64) for boundary in boundaries])
    width, height = points.max(axis=0) - points.min(axis=0)
    cells = math.ceil(width / DEFAULT_GRID_RESOLUTION) * math.ceil(height / DEFAULT_GRID_RESOLUTION)
    if cells > MAX_GRID_CELLS:
        problems.add(("zones",), f"the world spans {width:,.0f} m x {height:,.0f} m, a grid of {cells:,} cells at "
                                 f"{DEFAULT_GRID_RESOLUTION} m; at most {MAX_GRID_CELLS:,} cells "
                                 f"({MAX_GRID_CELLS * DEFAULT_GRID_RESOLUTION ** 2:,.0f} m^2 of bounding box) are supported")


def _close_pairs(positions: NDArray[np.float64], radius: float) -> list[tuple[int, int]]:
    """Index pairs (i < j, sorted) of points at most `radius` apart, from buckets of side `radius`: each
    point meets only the points of its own and the eight next buckets (a 20,000-door world in
    milliseconds, without scipy.spatial's half-second import on every reader's start)."""
    if radius <= 0:
        return []
    buckets: dict[tuple[int, int], list[int]] = {}
    for k, (x, y) in enumerate(positions):
        buckets.setdefault((math.floor(x / radius), math.floor(y / radius)), []).append(k)
    pairs: list[tuple[int, int]] = []
    for (bx, by), members in buckets.items():
        near = [m for dx in (-1, 0, 1) for dy in (-1, 0, 1) for m in buckets.get((bx + dx, by + dy), ())]
        for i in members:
            for j in near:
                if i < j and math.dist(positions[i], positions[j]) <= radius:
                    pairs.append((i, j))
    return sorted(pairs)


def _validate(zones: list[_DraftZone], obstacles: list[_DraftObstacle], problems: _Problems) -> dict[int, tuple[Point2, Point2]]:
    """Cross-field checks; returns each valid door's (along, normal) keyed by id(draft door)."""
    door_frames: dict[int, tuple[Point2, Point2]] = {}

    # Names are unique across the whole world so any RoI can be found by name alone.
    seen: dict[str, YamlPath] = {}

    def claim(name: str | None, path: YamlPath) -> None:
        if name is None:
            return
        if name in seen:
            first = seen[name]
            problems.add(path + ("name",), f"duplicate name {name!r}: already used at {format_path(first)} "
                                           f"(line {problems.line_of(first)}); every zone, door, entity and obstacle name must be unique")
        else:
            seen[name] = path

    for zone in zones:
        claim(zone.name, zone.path)
        for door in zone.doors:
            claim(door.name, door.path)
        for entity in zone.entities:
            claim(entity.name, entity.path)
    for obstacle in obstacles:
        claim(obstacle.name, obstacle.path)
    if OUTSIDE in seen:
        problems.add(seen[OUTSIDE] + ("name",), f"{OUTSIDE!r} is reserved for doors that leave the building")

    shaped = [zone for zone in zones if zone.polygon is not None]
    # A spatial index keeps every cross-zone check near linear: 20,000 zones load in seconds, where
    # all pairs took minutes. The tree returns candidate pairs whose polygons intersect.
    zone_shapes = np.array([zone.polygon for zone in shaped], dtype=object)
    zone_tree = shapely.STRtree(zone_shapes)
    if len(shaped) > 1:
        left, right = zone_tree.query(zone_shapes, predicate="intersects")
        ordered = left < right
        left, right = left[ordered], right[ordered]
        overlaps = shapely.area(shapely.intersection(zone_shapes[left], zone_shapes[right]))
        for i, j, overlap in sorted(zip(left.tolist(), right.tolist(), overlaps.tolist())):
            if overlap > OVERLAP_AREA_TOLERANCE:
                first, second = shaped[i], shaped[j]
                problems.add(second.path + ("boundary",),
                             f"zone {second.name!r} overlaps zone {first.name!r} ({format_path(first.path)}, "
                             f"line {problems.line_of(first.path)}) by {overlap:.2f} m^2; zones may share edges but not area")

    by_name = {zone.name: zone for zone in zones if zone.name is not None}
    zone_names = sorted(by_name)
    all_doors: list[_DraftDoor] = []
    for zone in zones:
        for door in zone.doors:
            all_doors.append(door)
            if door.leads_to is not None and door.leads_to != OUTSIDE and door.leads_to not in by_name:
                close = difflib.get_close_matches(door.leads_to, zone_names, n=2)
                hint = f"; did you mean {', '.join(close)}?" if close else ""
                problems.add(door.path + ("leads_to",), f"door {door.name!r} leads_to unknown zone {door.leads_to!r}{hint} "
                                                         f"(use a zone name or {OUTSIDE!r})")
            if door.leads_to == zone.name:
                problems.add(door.path + ("leads_to",), f"door {door.name!r} leads_to its own zone {zone.name!r}")
            if zone.polygon is None or door.position is None:
                continue
            position = Point(door.position)
            distance = zone.polygon.exterior.distance(position)
            if distance > ON_BOUNDARY_TOLERANCE:
                problems.add(door.path + ("position",),
                             f"door {door.name!r} at {list(door.position)} is not on the boundary of its zone "
                             f"{zone.name!r} ({distance:.2f} m away)")
                continue
            along, normal = _door_geometry(door, zone.polygon)
            if door.width is None:
                continue
            opening = _opening(door.position, door.width, along)
            if not _lies_on(opening, zone.polygon):
                problems.add(door.path + ("width",),
                             f"door {door.name!r} is {door.width} m wide but runs past the corner of the wall of "
                             f"zone {zone.name!r}; narrow it or move its position")
                continue
            other = by_name.get(door.leads_to or "")
            if other is not None and other.polygon is not None:
                other_distance = other.polygon.exterior.distance(position)
                if other_distance > ON_BOUNDARY_TOLERANCE:
                    problems.add(door.path + ("position",),
                                 f"door {door.name!r} at {list(door.position)} leads_to {other.name!r} but is not on "
                                 f"that zone's boundary ({other_distance:.2f} m away); a door must sit on the wall both zones share")
                    continue
                if not _lies_on(opening, other.polygon):
                    problems.add(door.path + ("width",),
                                 f"door {door.name!r} is {door.width} m wide but the wall it shares with "
                                 f"{other.name!r} is shorter there; narrow it or move its position")
                    continue
            if door.leads_to == OUTSIDE:
                near = np.sort(zone_tree.query(position, predicate="dwithin", distance=ON_BOUNDARY_TOLERANCE))
                for neighbour in (shaped[index] for index in near.tolist()):
                    if neighbour is zone:
                        continue
                    if neighbour.polygon.exterior.distance(position) <= ON_BOUNDARY_TOLERANCE:
                        problems.add(door.path + ("leads_to",),
                                     f"door {door.name!r} leads outside but sits on the wall shared with zone "
                                     f"{neighbour.name!r}; set leads_to: {neighbour.name}")
                        break
            door_frames[id(door)] = (along, normal)

    # A door declared once cuts both walls; declaring it again from the other side is a mistake.
    placed = [door for door in all_doors if id(door) in door_frames]
    if len(placed) > 1:
        # Candidate pairs within the widest half-width (grid buckets), then the exact per-pair test.
        positions = np.array([door.position for door in placed], dtype=np.float64)
        width = {id(door): door.width or 0.0 for door in placed}  # a placed door has passed its checks: it has one
        widest = max(width.values())
        for i, j in _close_pairs(positions, widest / 2):
            first, second = placed[i], placed[j]
            if math.dist(positions[i], positions[j]) < max(width[id(first)], width[id(second)]) / 2:
                problems.add(second.path + ("position",),
                             f"door {second.name!r} overlaps door {first.name!r} ({format_path(first.path)}); "
                             f"declare a door between two zones once, in one of them")

    blockers: list[tuple[str, Polygon]] = []
    for zone in zones:
        for entity in zone.entities:
            if entity.polygon is None:
                continue
            footprint = entity.polygon
            blockers.append((entity.name or "?", footprint))
            if zone.polygon is not None and not _covers_with_tolerance(zone.polygon, footprint):
                problems.add(entity.path + ("footprint",),
                             f"entity {entity.name!r} footprint is not inside its zone {zone.name!r}")
    zone_union = unary_union([z.polygon for z in shaped]) if shaped else None
    for obstacle in obstacles:
        if obstacle.polygon is None:
            continue
        footprint = obstacle.polygon
        blockers.append((obstacle.name or "?", footprint))
        if zone_union is not None and not _covers_with_tolerance(zone_union, footprint):
            problems.add(obstacle.path + ("footprint",), f"obstacle {obstacle.name!r} is not inside the zones")

    blocker_shapes = np.array([shape for _, shape in blockers], dtype=object)
    for zone in zones:
        for entity in zone.entities:
            if entity.interaction_point is None:
                continue
            point = Point(entity.interaction_point)
            here = entity.path + ("interaction_point",)
            if entity.polygon is not None and entity.polygon.distance(point) <= 1e-6:
                problems.add(here, f"interaction_point {list(entity.interaction_point)} of entity {entity.name!r} is inside "
                                   f"its own footprint; put it where a person stands to use it")
            elif zone.polygon is not None and not zone.polygon.contains(point):
                problems.add(here, f"interaction_point {list(entity.interaction_point)} of entity {entity.name!r} is "
                                   f"outside its zone {zone.name!r}")
            elif blockers:
                hits = np.flatnonzero(shapely.covers(blocker_shapes, point))
                other_names = [blockers[i][0] for i in hits if blockers[i][0] != entity.name]
                if other_names:
                    problems.add(here, f"interaction_point {list(entity.interaction_point)} of entity "
                                       f"{entity.name!r} is inside the footprint of {other_names[0]!r}")

    things = [(entity.path, "entity", entity.name, entity.polygon) for zone in zones for entity in zone.entities
              if entity.polygon is not None]
    things += [(obstacle.path, "obstacle", obstacle.name, obstacle.polygon) for obstacle in obstacles
               if obstacle.polygon is not None]
    thing_shapes = np.array([thing[3] for thing in things], dtype=object)
    for door in placed:
        if not things:
            break
        along, _ = door_frames[id(door)]
        opening = _opening(door.position, door.width, along)  # type: ignore[arg-type]
        for index in np.flatnonzero(shapely.dwithin(thing_shapes, opening, DOOR_CLEARANCE)):
            path, kind, thing_name, _ = things[index]
            problems.add(path + ("footprint",), f"{kind} {thing_name!r} blocks door {door.name!r}: keep footprints at "
                                                f"least {DOOR_CLEARANCE} m from a door opening")

    # Judge reachability on declared links, so one misplaced door is reported once, not again as an island.
    _check_connectivity(zones, all_doors, by_name, problems)
    return door_frames


def _check_connectivity(zones: list[_DraftZone], doors: list[_DraftDoor], by_name: dict[str, _DraftZone],
                        problems: _Problems) -> None:
    """Every zone must be reachable from the first through doors (the grid test checks geometry too)."""
    if not by_name:
        return
    neighbours: dict[str, set[str]] = {name: set() for name in by_name}
    for door in doors:
        if door.zone in neighbours and door.leads_to in neighbours:
            neighbours[door.zone].add(door.leads_to)
            neighbours[door.leads_to].add(door.zone)
    start = next(iter(by_name))
    reached = {start}
    frontier = [start]
    while frontier:
        for nxt in neighbours[frontier.pop()]:
            if nxt not in reached:
                reached.add(nxt)
                frontier.append(nxt)
    for name, zone in by_name.items():
        if name not in reached:
            problems.add(zone.path + ("doors",), f"zone {name!r} cannot be reached from zone {start!r} through doors")


def _free_anchor(zone: _DraftZone, obstacles: Sequence[Polygon] = (), clearance: float = 0.4) -> Point2:
    """A point inside the zone and clear of its entities and of the world's obstacles, as close to the
    centroid as possible (plans and fields start from it: a rack over the centre must not hold it)."""
    polygon = zone.polygon
    assert polygon is not None
    footprints = [e.polygon for e in zone.entities if e.polygon is not None]
    footprints += [o for o in obstacles if o.intersects(polygon)]
    centroid = polygon.centroid
    clear_of_walls = polygon.contains(centroid) and polygon.exterior.distance(centroid) >= clearance
    if clear_of_walls and all(f.distance(centroid) >= clearance for f in footprints):
        return (round(centroid.x, 3), round(centroid.y, 3))
    free = polygon.buffer(-clearance)
    if footprints:
        free = free.difference(unary_union(footprints).buffer(clearance))
    if free.is_empty:
        free = polygon
    # Nearest point of a slightly shrunk free area, so the anchor is strictly inside, not on its edge.
    inner = free.buffer(-0.05)
    target = inner if not inner.is_empty else free
    point = shapely.ops.nearest_points(target, centroid)[0]
    if not free.contains(point):
        point = free.representative_point()
    return (round(point.x, 3), round(point.y, 3))


def parse_world(text: str, source: str = "<string>") -> tuple[World | None, list[WorldProblem]]:
    """Parse and validate world YAML text; returns the world (None if any problem) and every problem."""
    try:
        data, lines, repeated = compose_yaml(text)
    except yaml.MarkedYAMLError as error:
        mark = error.problem_mark or error.context_mark
        line = mark.line + 1 if mark is not None else None
        detail = " ".join(part for part in (error.context, error.problem) if part)
        if "maximum nesting depth" in detail:
            # PyYAML 6.0.4 and later stop deep nesting in the parser, before our own depth check sees it.
            problem = f"the YAML nests more than its parser allows ({detail})"
            return None, [WorldProblem(source, "(document)", line, problem)]
        return None, [WorldProblem(source, "(document)", line, f"broken YAML: {detail}")]
    except yaml.YAMLError as error:
        return None, [WorldProblem(source, "(document)", None, f"broken YAML: {error}")]
    except InputLimitError as error:
        return None, [WorldProblem(source, "(document)", error.line, str(error))]
    problems = _Problems(source, lines)
    for path in repeated:
        problems.items.append(WorldProblem(source, format_path(path[:-1]), problems.line_of(path),
                                           f"key {path[-2]!r} appears twice in the same mapping; the first value would be lost"))
    if not isinstance(data, dict):
        problems.add((), f"a world file must be a mapping with name and zones, got {type(data).__name__}")
        return None, problems.items
    if data and not any(key in data for key in WORLD_KEYS):
        # Not a world at all: one problem, and nothing of the file's content quoted back.
        problems.add((), f"not a world file: none of {', '.join(WORLD_KEYS)} at its top level "
                         f"({len(data)} other keys); a world starts with `name:` and `zones:`")
        return None, problems.items
    _check_keys(data, WORLD_KEYS, (), problems)
    name = _read_name(data, (), problems)
    description = _read_str(data, "description", (), problems, required=False) or ""
    raw_zones = data.get("zones")
    if not isinstance(raw_zones, list) or not raw_zones:
        problems.add(("zones",) if "zones" in data else (), "zones must be a non-empty list of zones")
        raw_zones = []
    if len(raw_zones) > MAX_ZONES:
        problems.add(("zones",), f"the world has {len(raw_zones):,} zones; at most {MAX_ZONES:,} are supported")
        return None, problems.items
    zones = [zone for index, item in enumerate(raw_zones)
             if (zone := _read_zone(item, ("zones", index), problems)) is not None]
    obstacles = [obstacle for index, item in enumerate(_read_list(data, "obstacles", (), problems))
                 if (obstacle := _read_obstacle(item, ("obstacles", index), problems)) is not None]
    _check_extent(zones, problems)
    door_frames = _validate(zones, obstacles, problems)
    if problems.items:
        return None, sorted(problems.items, key=lambda problem: problem.line or 0)

    obstacle_footprints = [Polygon(o.footprint) for o in obstacles]
    built_zones = []
    for zone in zones:
        assert zone.boundary is not None  # a zone without one is a problem, and problems returned above
        doors = tuple(Door(d.name, zone.name, d.position, d.width, d.leads_to, d.exit, d.description,  # type: ignore[arg-type]
                           d.aliases, d.tags, *door_frames[id(d)]) for d in zone.doors)
        entities = tuple(Entity(e.name, zone.name, e.type, e.footprint, e.interaction_point, e.tags,  # type: ignore[arg-type]
                                e.description, e.aliases) for e in zone.entities)
        built_zones.append(Zone(zone.name, zone.type, zone.description, zone.aliases, zone.tags,  # type: ignore[arg-type]
                                zone.boundary, doors, entities, _free_anchor(zone, obstacle_footprints)))
    zone_tree = shapely.STRtree([zone.polygon for zone in zones])
    built_obstacles = []
    for obstacle in obstacles:
        footprint = Polygon(obstacle.footprint)
        # The first zone in file order that the footprint touches is its home.
        touching = zone_tree.query(footprint, predicate="intersects")
        home = zones[int(touching.min())].name if len(touching) else None
        built_obstacles.append(Obstacle(obstacle.name, obstacle.footprint, obstacle.type,  # type: ignore[arg-type]
                                        obstacle.description, home))
    fingerprint = hashlib.sha1(text.encode("utf-8")).hexdigest()
    # Text that did not come from a file (tests, generated worlds) has no source path.
    source_path = Path(source) if source != "<string>" and Path(source).is_file() else None
    return World(name, description, built_zones, built_obstacles, source_path, fingerprint), []  # type: ignore[arg-type]


def _read_world_text(file: Path) -> str:
    """The file's text, refusing devices, pipes and files over MAX_WORLD_FILE_BYTES before reading."""
    return read_text_bounded(file, MAX_WORLD_FILE_BYTES, "world file")


def read_world_file(name_or_path: str | os.PathLike[str]) -> tuple[Path, str]:
    """The resolved path and the text of a world (a shipped name or a path).

    WorldError when there is nothing to check: the name is unknown, or the file is missing, not a
    regular file, over MAX_WORLD_FILE_BYTES, unreadable or not UTF-8. `grove worlds check` tells this
    "could not read it" (exit 2) apart from the problems of a file it did read (exit 1).
    """
    path = resolve_world_path(name_or_path)
    try:
        return path, _read_world_text(path)
    except OSError as error:
        raise WorldError(f"cannot read world file {path}: {error.strerror}") from None
    except InputLimitError as error:
        raise WorldError(str(error)) from None


def check_world_file(path: str | os.PathLike[str]) -> list[WorldProblem]:
    """Every problem in a world file (empty when it loads)."""
    file = Path(path)
    try:
        text = _read_world_text(file)
    except InputLimitError as error:
        return [WorldProblem(str(file), "(document)", None, str(error))]
    return parse_world(text, str(file))[1]


# --------------------------------------------------------------------------------------------
# Finding and loading


def list_worlds() -> list[str]:
    """Names of the shipped worlds (the YAML files in the worlds directory)."""
    directory = worlds_dir()
    if not directory.is_dir():
        return []
    return sorted(path.stem for path in directory.glob("*.yaml"))


def resolve_world_path(name_or_path: str | os.PathLike[str]) -> Path:
    text = str(name_or_path)
    candidate = Path(text).expanduser()
    looks_like_path = os.sep in text or "/" in text or text.endswith((".yaml", ".yml"))
    if looks_like_path:
        try:
            # A folder, a device (/dev/zero), a pipe or an oversized file: say what it is rather than
            # "missing", before anything opens it.
            check_regular_file(candidate, MAX_WORLD_FILE_BYTES, "world file")
        except InputLimitError as error:
            raise WorldError(str(error)) from None
        return candidate.resolve()
    shipped = worlds_dir() / f"{text}.yaml"
    if shipped.is_file():
        return shipped.resolve()
    if candidate.is_file():
        return candidate.resolve()
    raise WorldError(_unknown_name_message("there is no shipped world", text, list_worlds())
                     + "; pass a path to load your own world YAML")


_LOADED: dict[tuple[str, int, int], World] = {}


def load_world(name_or_path: str | os.PathLike[str]) -> World:
    """Load a shipped world by name ("hospital") or a world YAML by path; WorldError lists every problem."""
    path = resolve_world_path(name_or_path)
    try:
        stat = path.stat()
        key = (str(path), stat.st_mtime_ns, stat.st_size)
        if key in _LOADED:
            return _LOADED[key]
        text = _read_world_text(path)
    except OSError as error:
        raise WorldError(f"cannot read world file {path}: {error.strerror}") from None
    except InputLimitError as error:
        raise WorldError(str(error)) from None
    world, problems = parse_world(text, str(path))
    if world is None:
        count = len(problems)
        if count == 1:
            # One problem fits on one line, which is what a script or a terminal shows first.
            raise WorldError(f"world file {problems[0]}", problems)
        listing = "\n".join(f"  {problem}" for problem in problems)
        raise WorldError(f"world file {path} has {count} problems:\n{listing}", problems)
    _LOADED[key] = world
    return world
