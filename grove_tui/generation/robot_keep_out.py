"""The places the robot's clause says it keeps out of ("drives to the pharmacy, avoiding the cafeteria",
"without going through the main waiting room"; `RobotReading.avoid`): its path is planned round them with
the groups' keep-out planner (keep_out.py), and its row of the report says, per place, whether the plan
keeps out. A start or goal inside such a place, or no way round it, is said in the notes and fails the
claim before any run: the report does not pretend."""

from __future__ import annotations

from collections.abc import Sequence

import shapely

from grove_tui.errors import WorldError
from grove_tui.generation.keep_out import keep_out_shape
from grove_tui.language.model import RobotReading
from grove_tui.scenario.report import FAILS, Claim
from grove_tui.world.model import World, Zone

Point = tuple[float, float]
# A path that only grazes a room's edge (its doorway, the margin round it) has not been in it.
INSIDE_MARGIN = 0.3


def robot_kept_out(world: World, asked: RobotReading | None) -> tuple[str, ...]:
    """The world places the robot's clause says it keeps out of (unknown names dropped)."""
    if asked is None:
        return ()
    out: list[str] = []
    for name in asked.avoid:
        try:
            world.find(name)
        except WorldError:
            continue
        out += [] if name in out else [name]
    return tuple(out)


def kept_out_zones(world: World, names: Sequence[str]) -> set[str]:
    """The rooms among the places kept out of (a start is never picked in one)."""
    out: set[str] = set()
    for name in names:
        try:
            place = world.find(name)
        except WorldError:
            continue
        if isinstance(place, Zone):
            out.add(place.name)
    return out


def _inside(world: World, name: str) -> shapely.Geometry | None:
    """The ground that counts as in the place: a room less its edge, a door's or thing's disc."""
    try:
        place = world.find(name)
    except WorldError:
        return None
    if isinstance(place, Zone):
        return place.polygon.buffer(-INSIDE_MARGIN)
    return keep_out_shape(world, name)


def broken_keep_out(world: World, name: str, path: Sequence[Point]) -> str:
    """Why the planned path does not keep out of `name` ("" when it does): it starts there, ends there,
    or goes through it."""
    shape = _inside(world, name)
    if shape is None or shape.is_empty or not path:
        return ""
    if shape.contains(shapely.Point(path[0])):
        return f"the robot starts in {name}"
    if shape.contains(shapely.Point(path[-1])):
        return f"the robot's goal is in {name}"
    line = shapely.LineString(path) if len(path) > 1 else shapely.Point(path[0])
    if line.intersects(shape):
        return f"the robot's planned path goes through {name}: no way round"
    return ""


def keep_out_notes(world: World, names: Sequence[str], path: Sequence[Point]) -> list[str]:
    """The plan's notes for the places its path does not keep out of."""
    return [f"{why}, which the sentence says it keeps out of" for why in
            (broken_keep_out(world, n, path) for n in names) if why]


def robot_keep_out_claim(claim: Claim, world: World, path: Sequence[Point], seconds: float) -> Claim:
    """A place's keep_out claim for the robot's row (`claim` built as a group's is): ✗ now when the plan
    already breaks it, else judged on the run once its drive would be over."""
    place = claim.place or claim.asked
    why = broken_keep_out(world, place, path)
    claim = Claim(claim.kind, claim.asked, f"drive round {place}", zone=claim.zone, place=claim.place,
                  point=claim.point, radius=claim.radius, share=1.0, needs_seconds=round(seconds * 1.3 + 10.0, 1))
    return claim.checked(FAILS, why) if why else claim
