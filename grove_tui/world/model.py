"""The semantic world: zones, doors, entities and obstacles (loaded by `grove_tui.world.loader`).

One YAML file is the single source of truth for both geometry and meaning: walls are the
zone boundaries minus door openings (plus obstacle and entity footprints), and every zone,
door and entity is a Region of Interest (RoI) that prompts can name.

Loading validates everything it can and reports *all* problems at once, each naming the file,
the YAML path (``zones[3].doors[1].width``) and the line, because worlds are written by hand.
"""

from __future__ import annotations

import difflib
import hashlib
import re
from collections.abc import Iterable, Iterator
from dataclasses import dataclass
from functools import cached_property
from pathlib import Path
from typing import Literal

import numpy as np
import shapely
import shapely.ops
from shapely.geometry import LineString, Point, Polygon
from shapely.geometry.base import BaseGeometry
from shapely.ops import unary_union

from grove_tui.errors import WorldError

Point2 = tuple[float, float]

OUTSIDE = "outside"
# A door position may sit this far from the boundary line and still count as on it (metres).
ON_BOUNDARY_TOLERANCE = 0.05
# Areas below this are rounding noise, not an overlap (square metres).
OVERLAP_AREA_TOLERANCE = 1e-4
# Entities closer than this to a door opening block the doorway for people and the planner.
DOOR_CLEARANCE = 0.5
# Walls are drawn as lines; `walkable()` removes this half-thickness around them so the
# polygon does not connect rooms through walls (JuPedSim and similar tools need that).
WALL_HALF_THICKNESS = 0.05
# Half-width of the band that cuts a door opening out of its wall line (metres).
DOOR_CUT = 0.02

SNAKE_CASE = re.compile(r"^[a-z][a-z0-9]*(_[a-z0-9]+)*$")


# --------------------------------------------------------------------------------------------
# Errors


@dataclass(frozen=True)
class WorldProblem:
    """One thing wrong with a world file, located precisely enough to fix it."""

    file: str
    path: str
    line: int | None
    message: str

    def __str__(self) -> str:
        where = f"{self.file}:{self.line}" if self.line is not None else self.file
        return f"{where}: {self.path}: {self.message}"


# --------------------------------------------------------------------------------------------
# Model


@dataclass(frozen=True)
class Door:
    name: str
    zone: str
    position: Point2
    width: float
    leads_to: str
    exit: bool
    description: str = ""
    aliases: tuple[str, ...] = ()
    tags: tuple[str, ...] = ()
    # Unit vector along the wall and unit normal pointing into `zone`, fixed at load time.
    along: Point2 = (1.0, 0.0)
    normal: Point2 = (0.0, 1.0)

    def inward_point(self, d: float = 0.6) -> Point2:
        """A point `d` metres from the door centre, inside the zone that declares the door."""
        return (self.position[0] + d * self.normal[0], self.position[1] + d * self.normal[1])

    def outward_point(self, d: float = 0.6) -> Point2:
        """A point `d` metres from the door centre on the `leads_to` side (or outside)."""
        return (self.position[0] - d * self.normal[0], self.position[1] - d * self.normal[1])

    @property
    def opening(self) -> tuple[Point2, Point2]:
        """The two jambs of the door: the cut made in the wall."""
        half = self.width / 2.0
        px, py = self.position
        ax, ay = self.along
        return ((px - half * ax, py - half * ay), (px + half * ax, py + half * ay))

    def connects(self, zone_name: str) -> bool:
        return zone_name in (self.zone, self.leads_to)


@dataclass(frozen=True)
class Entity:
    name: str
    zone: str
    type: str
    footprint: tuple[Point2, ...]
    interaction_point: Point2
    tags: tuple[str, ...] = ()
    description: str = ""
    aliases: tuple[str, ...] = ()

    @cached_property
    def polygon(self) -> Polygon:
        return Polygon(self.footprint)


@dataclass(frozen=True)
class Obstacle:
    name: str
    footprint: tuple[Point2, ...]
    type: str = "obstacle"
    description: str = ""
    zone: str | None = None

    @cached_property
    def polygon(self) -> Polygon:
        return Polygon(self.footprint)


@dataclass(frozen=True)
class Zone:
    name: str
    type: str
    description: str
    aliases: tuple[str, ...]
    tags: tuple[str, ...]
    boundary: tuple[Point2, ...]
    doors: tuple[Door, ...]
    entities: tuple[Entity, ...]
    # A free point near the centroid (not inside any entity), used as the zone's goal point.
    anchor: Point2 = (0.0, 0.0)

    @cached_property
    def polygon(self) -> Polygon:
        return Polygon(self.boundary)

    @cached_property
    def centroid(self) -> Point2:
        c = self.polygon.centroid
        return (float(c.x), float(c.y))

    @property
    def area(self) -> float:
        return float(self.polygon.area)


@dataclass(frozen=True)
class RoI:
    """A Region of Interest as prompt matching sees it: names, words and one point to go to."""

    kind: Literal["zone", "door", "entity"]
    name: str
    zone: str
    type: str
    tags: tuple[str, ...]
    aliases: tuple[str, ...]
    description: str
    point: Point2
    polygon: tuple[Point2, ...] | None
    leads_to: str | None = None
    exit: bool = False

    def words(self) -> list[str]:
        """Every word a prompt might use for this RoI (name parts, type, aliases, tags)."""
        found: list[str] = []
        for text in (self.name, self.type, *self.aliases, *self.tags):
            for word in re.split(r"[\s_\-]+", text.lower()):
                if word and word not in found:
                    found.append(word)
        return found


class World:
    """A loaded, validated world. Immutable: build a new one by loading another file."""

    def __init__(self, name: str, description: str, zones: Iterable[Zone],
                 obstacles: Iterable[Obstacle] = (), source: Path | None = None,
                 fingerprint: str | None = None) -> None:
        self._name = name
        self._description = description
        self._zones = tuple(zones)
        self._obstacles = tuple(obstacles)
        self._source = source
        self._by_zone = {zone.name: zone for zone in self._zones}
        self._fingerprint = fingerprint or hashlib.sha1(repr((name, self._zones, self._obstacles)).encode()).hexdigest()

    name = property(lambda self: self._name)
    description = property(lambda self: self._description)
    zones = property(lambda self: self._zones)
    obstacles = property(lambda self: self._obstacles)
    source = property(lambda self: self._source)
    fingerprint = property(lambda self: self._fingerprint, doc="Content hash; grids are cached on it.")

    def __repr__(self) -> str:
        return f"World({self._name!r}, zones={len(self._zones)}, source={str(self._source)!r})"

    # --- lookups ---------------------------------------------------------------------------

    def zone(self, name: str) -> Zone:
        try:
            return self._by_zone[name]
        except KeyError:
            raise WorldError(_unknown_name_message(f"world {self._name!r} has no zone", name, list(self._by_zone))) from None

    def find(self, name: str) -> Zone | Door | Entity:
        """Any RoI by exact name; then by case-insensitive name; then by a unique alias."""
        index = self._named
        if name in index:
            return index[name]
        lowered = name.strip().lower().replace(" ", "_")
        for key, value in index.items():
            if key.lower() == lowered:
                return value
        by_alias = [value for value in index.values()
                    if any(alias.lower() == name.strip().lower() for alias in getattr(value, "aliases", ()))]
        if len(by_alias) == 1:
            return by_alias[0]
        if len(by_alias) > 1:
            names = ", ".join(item.name for item in by_alias)
            raise WorldError(f"world {self._name!r}: {name!r} is an alias of several places ({names}); use one of those names")
        raise WorldError(_unknown_name_message(f"world {self._name!r} has no zone, door or entity", name, list(index)))

    def zone_of_place(self, name: str | None) -> str | None:
        """The zone a place lies in: a zone's own name, a door's or entity's zone; None for an empty or
        unknown name (or an alias several places share), so callers can fall back."""
        if not name:
            return None
        try:
            place = self.find(name)
        except WorldError:
            return None
        return place.zone if isinstance(place, (Door, Entity)) and place.zone else place.name

    @cached_property
    def _named(self) -> dict[str, Zone | Door | Entity]:
        named: dict[str, Zone | Door | Entity] = {}
        for zone in self._zones:
            named[zone.name] = zone
            for door in zone.doors:
                named[door.name] = door
            for entity in zone.entities:
                named[entity.name] = entity
        return named

    def zone_at(self, x: float, y: float) -> Zone | None:
        point = Point(x, y)
        for zone in self._zones:
            if zone.polygon.covers(point):
                return zone
        return None

    def doors(self) -> list[Door]:
        return [door for zone in self._zones for door in zone.doors]

    def doors_of(self, zone_name: str) -> list[Door]:
        """Doors declared by the zone and doors other zones declared into it."""
        self.zone(zone_name)
        return [door for door in self.doors() if door.connects(zone_name)]

    def exits(self) -> list[Door]:
        return [door for door in self.doors() if door.exit]

    def entities(self) -> list[Entity]:
        return [entity for zone in self._zones for entity in zone.entities]

    def entities_of_type(self, entity_type: str) -> list[Entity]:
        return [entity for entity in self.entities() if entity.type == entity_type]

    # --- geometry --------------------------------------------------------------------------

    def bounds(self) -> tuple[float, float, float, float]:
        xmin, ymin, xmax, ymax = self._zone_union.bounds
        return (float(xmin), float(ymin), float(xmax), float(ymax))

    @cached_property
    def _zone_union(self) -> BaseGeometry:
        return unary_union([zone.polygon for zone in self._zones])

    def outline(self) -> BaseGeometry:
        """The union of all zones: the building's floor, ignoring walls and furniture."""
        return self._zone_union

    @cached_property
    def _room_walls(self) -> BaseGeometry:
        """Zone boundaries, shared edges merged once, with every door opening cut out."""
        outlines = unary_union([zone.polygon.boundary for zone in self._zones])
        doors = self.doors()
        if not doors:
            return outlines
        # Each opening is cut with a thin band (door positions may sit a little off the line). The
        # band also bites DOOR_CUT into walls that run across the door line, such as the side walls
        # of a corridor whose door spans its whole end; those bits go back, so jambs stay closed
        # corners instead of 2 cm gaps whose two loose wall ends each repelled (issue 19).
        openings = [LineString(door.opening) for door in doors]
        bands = unary_union([line.buffer(DOOR_CUT, cap_style="flat") for line in openings])
        kept = outlines.difference(bands)
        cut = outlines.intersection(bands)
        index = shapely.STRtree(openings)
        across = []
        for x1, y1, x2, y2 in _segments_of(cut):
            length = ((x2 - x1) ** 2 + (y2 - y1) ** 2) ** 0.5
            if length <= 1e-12:
                continue
            door = doors[int(index.nearest(Point((x1 + x2) / 2.0, (y1 + y2) / 2.0)))]
            if abs((x2 - x1) * door.along[0] + (y2 - y1) * door.along[1]) / length < 0.5:
                across.append(LineString([(x1, y1), (x2, y2)]))
        return unary_union([kept, *across]) if across else kept

    @cached_property
    def _wall_segments(self) -> np.ndarray:
        footprints = [entity.polygon.exterior for entity in self.entities()]
        footprints += [obstacle.polygon.exterior for obstacle in self._obstacles]
        lines = unary_union([self._room_walls, *footprints])
        merged = _drop_collinear(shapely.line_merge(lines))
        segments = np.array(list(_segments_of(merged)), dtype=np.float64).reshape(-1, 4)
        lengths = np.hypot(segments[:, 2] - segments[:, 0], segments[:, 3] - segments[:, 1])
        segments = segments[lengths > 1e-9]
        segments.flags.writeable = False
        return segments

    @cached_property
    def _room_wall_segments(self) -> np.ndarray:
        merged = _drop_collinear(shapely.line_merge(self._room_walls))
        segments = np.array(list(_segments_of(merged)), dtype=np.float64).reshape(-1, 4)
        segments = segments[np.hypot(segments[:, 2] - segments[:, 0], segments[:, 3] - segments[:, 1]) > 1e-9]
        segments.flags.writeable = False
        return segments

    def room_walls(self) -> np.ndarray:
        """(M, 4) segments of the building walls only (zone boundaries minus doors, no footprints)."""
        return self._room_wall_segments

    def walls(self) -> np.ndarray:
        """(M, 4) float64 segments x1, y1, x2, y2: walls minus door openings, plus footprint edges."""
        return self._wall_segments

    @cached_property
    def _walkable(self) -> BaseGeometry:
        blocked = [entity.polygon for entity in self.entities()] + [obstacle.polygon for obstacle in self._obstacles]
        blocked.append(self._room_walls.buffer(WALL_HALF_THICKNESS, cap_style="flat"))
        return self._zone_union.difference(unary_union(blocked))

    def walkable(self) -> BaseGeometry:
        """Union of zones minus entity and obstacle footprints and thin walls (door gaps stay open)."""
        return self._walkable

    @cached_property
    def _roi_index(self) -> tuple[RoI, ...]:
        rois: list[RoI] = []
        for zone in self._zones:
            rois.append(RoI("zone", zone.name, zone.name, zone.type, zone.tags, zone.aliases, zone.description,
                            zone.anchor, zone.boundary))
        for zone in self._zones:
            for door in zone.doors:
                rois.append(RoI("door", door.name, zone.name, "exit" if door.exit else "door", door.tags, door.aliases,
                                door.description, door.position, None, leads_to=door.leads_to, exit=door.exit))
        for zone in self._zones:
            for entity in zone.entities:
                rois.append(RoI("entity", entity.name, zone.name, entity.type, entity.tags, entity.aliases,
                                entity.description, entity.interaction_point, entity.footprint))
        return tuple(rois)

    def roi_index(self) -> list[RoI]:
        """Every zone, door and entity with its metadata and a point an agent can walk to."""
        return list(self._roi_index)

    def roi(self, name: str) -> RoI:
        for item in self._roi_index:
            if item.name == name:
                return item
        raise WorldError(_unknown_name_message(f"world {self._name!r} has no RoI", name, [r.name for r in self._roi_index]))


# Vertices per piece handed to GEOS's simplify: its Douglas-Peucker recursion goes as deep as a line
# has vertices, and a zigzag wall of ~80,000 overflowed the C stack (a segfault in `generate`).
_SIMPLIFY_PIECE = 5_000


def _drop_collinear(lines: BaseGeometry) -> BaseGeometry:
    """`shapely.simplify(lines, 0.0)` (vertices on a straight run dropped), with long lines simplified in
    pieces that share their end vertices, so the recursion stays shallow whatever the world. Lines of
    real worlds are far shorter than a piece and come out exactly as before."""
    parts = shapely.get_parts(lines)
    if all(shapely.get_num_coordinates(part) <= _SIMPLIFY_PIECE for part in parts):
        return shapely.simplify(lines, 0.0)
    pieces: list[BaseGeometry] = []
    for part in parts:
        coords = shapely.get_coordinates(part)
        if len(coords) <= _SIMPLIFY_PIECE:
            pieces.append(shapely.simplify(part, 0.0))
            continue
        for start in range(0, len(coords) - 1, _SIMPLIFY_PIECE - 1):
            pieces.append(shapely.simplify(LineString(coords[start:start + _SIMPLIFY_PIECE]), 0.0))
    return shapely.MultiLineString([piece for piece in pieces if not piece.is_empty])


def _segments_of(geometry: BaseGeometry) -> Iterator[tuple[float, float, float, float]]:
    if geometry.is_empty:
        return
    if isinstance(geometry, LineString) or geometry.geom_type == "LinearRing":
        coords = list(geometry.coords)
        for (x1, y1), (x2, y2) in zip(coords, coords[1:]):
            yield (x1, y1, x2, y2)
        return
    if hasattr(geometry, "geoms"):
        for part in geometry.geoms:
            yield from _segments_of(part)
        return
    if isinstance(geometry, Polygon):
        yield from _segments_of(geometry.exterior)


def _unknown_name_message(prefix: str, name: str, known: list[str]) -> str:
    close = difflib.get_close_matches(name, known, n=3)
    hint = f"; did you mean {', '.join(close)}?" if close else ""
    shown = ", ".join(sorted(known)[:40]) + (" ..." if len(known) > 40 else "")
    return f"{prefix} named {name!r}{hint} (known: {shown})"
