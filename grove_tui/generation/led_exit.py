"""The exit the robot leads people to, where the sentence names none in particular: the nearest to them.

"The robot leads a family to the exit" (airport, five exits): the reader picked one of the exits that fit
by its words ("west_entrance is in check_in_hall, named before"), or the roi model picked one, and the
robot drove there from wherever planning put it: 98 m to emergency_exit_east in one run. Where the exit is
picked among several that fit, the robot (and the people it leads, who set off beside it) now go to the
one nearest by planned path from where they set off (`nearest_exit`; when nobody said where that is,
not one it starts at: the nearest MIN_LEAD or more away); the report's reading carries that
exit for the robot and the group (`with_led_exit`), and still says which others fit.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import replace

import numpy as np

from grove_tui.generation.guided import guided_index
from typing import TypeVar

from grove_tui.language.model import FieldConfidence, GroupReading, PromptReading, RobotReading
from grove_tui.world.model import World

Point = tuple[float, float]
Subject = TypeVar("Subject", GroupReading, RobotReading)
NEAR_GOAL = 3.0
MIN_LEAD = 5.0  # metres: an exit nearer the start planning picked is where they already are, not led to  # metres: the robot's goal this near an exit's point is that exit


def fitting_exits(world: World, reading: PromptReading | None) -> tuple[str, ...]:
    """The exits that fit where the robot leads people, when it was picked among several (else ())."""
    if reading is None or reading.robot is None or reading.robot.task != "cross":
        return ()
    index = guided_index(reading)
    if index is None or reading.groups[index].robot_interaction != "follow":
        return ()  # evacuees it guides out leave by their own nearest exits (postprocess); it goes with them
    exits = [d.name for d in world.exits()]
    for subject in (reading.robot, reading.groups[index]):
        if subject.destination not in exits:
            continue
        c = next((c for c in subject.confidence if c.field == "destination"), None)
        if c is None or c.score >= 1.0:
            continue
        fit = tuple(dict.fromkeys(e for e in (subject.destination, *c.alternatives) if e in exits))
        if len(fit) > 1:
            return fit
    return ()


def _length(path: np.ndarray) -> float:
    p = np.asarray(path, dtype=float).reshape(-1, 2)
    return float(np.hypot(*np.diff(p, axis=0).T).sum()) if len(p) > 1 else 0.0


def nearest_exit(world: World, reading: PromptReading | None, start: Point | None, goal: Point | None,
                 pick_start: Callable[[], Point], point_of: Callable[[str], Point | None],
                 plan_path: Callable[[Point, Point, bool], np.ndarray], notes: list[str]) -> tuple[Point | None, Point | None]:
    """(start, goal) of a robot that leads people to an exit picked among several: its start as chosen (or
    picked now), its goal the fitting exit nearest by planned path from there."""
    fit = fitting_exits(world, reading)
    if not fit:
        return start, goal
    picked_here = start is None
    start = start if start is not None else pick_start()
    lengths: dict[str, tuple[float, Point]] = {}
    for name in fit:
        point = point_of(name)
        if point is None:
            continue
        try:
            lengths[name] = (_length(plan_path(start, point, True)), point)
        except Exception:  # no way there: not a fitting exit for this start
            continue
    if picked_here and any(length >= MIN_LEAD for length, _ in lengths.values()):
        # nobody said where they are: a start planning picked beside an exit leads nobody anywhere (2 m, and
        # "it started at west_fire_exit" ✗); of the exits MIN_LEAD or more away, the nearest
        lengths = {n: v for n, v in lengths.items() if v[0] >= MIN_LEAD}
    if not lengths:
        return start, goal
    best = min(lengths, key=lambda n: (lengths[n][0], n))
    notes[:] = [n for n in notes if not (n.startswith("the robot goes to ") and "the exit of the people it guides" in n
                                         and not n.startswith(f"the robot goes to {best},"))]
    others = ", ".join(f"{n} {lengths[n][0]:.0f} m" for n in sorted(lengths, key=lambda n: lengths[n][0]) if n != best)
    notes.append(f"the robot leads them to {best}, the nearest of the exits that fit ({lengths[best][0]:.0f} m; "
                 f"{others})")
    return start, lengths[best][1]


def with_led_exit(reading: PromptReading, robot: object | None, world: World) -> PromptReading:
    """The reading with the exit the robot drove to (the fitting exit at its goal) as the robot's and the led
    group's destination, the other fitting exits kept as alternatives the report lists."""
    fit = fitting_exits(world, reading)
    goal = getattr(robot, "goal", None) if robot is not None else None
    if not fit or goal is None or reading.robot is None:
        return reading
    points = {d.name: d.position for d in world.exits() if d.name in fit}
    chosen = min(points, key=lambda n: math.dist(points[n], goal))
    if math.dist(points[chosen], goal) > NEAR_GOAL:
        return reading

    def moved(subject: Subject) -> Subject:
        if subject.destination not in fit or subject.destination == chosen:
            return subject
        confidence = tuple(
            FieldConfidence(c.field, c.score, f"{c.reason}; the nearest of them to where they set off: {chosen}",
                            tuple(e for e in fit if e != chosen)) if c.field == "destination" else c
            for c in subject.confidence)
        return replace(subject, destination=chosen, confidence=confidence)

    index = guided_index(reading)
    groups = tuple(moved(g) if i == index else g for i, g in enumerate(reading.groups))
    return replace(reading, robot=moved(reading.robot), groups=groups)


def led_exit_of(reading: PromptReading, guided: str | None, world: World) -> str | None:
    """The exit the report says the robot goes to: the one `with_led_exit` set, over the guided people's."""
    if fitting_exits(world, reading) and reading.robot is not None and reading.robot.destination:
        return reading.robot.destination
    return guided


