"""The robot's motion carried by the people who follow it (round 18): "three students follow the robot
out into the stacks", "a child trails the robot to the café". The sentence gives the robot no clause
of its own, yet it leads: it crosses to where its followers go, from where they start."""

from __future__ import annotations

from collections.abc import Sequence

from grove_tui.language.model import GroupReading, RobotReading


def led_by_robot(robot: RobotReading | None, read: Sequence[GroupReading]) -> RobotReading | None:
    """The robot's own reading, or, when the sentence gives it none, a crossing to where the first
    group that follows it goes (None when no follower of the robot goes anywhere said)."""
    if robot is not None:
        return robot
    led = next((g for g in read if g.robot_interaction == "follow" and g.destination), None)
    if led is None:
        return None
    return RobotReading("cross", start=led.start, destination=led.destination, via=tuple(led.via), text=led.text,
                        confidence=tuple(c for c in led.confidence if c.field in ("start", "destination", "via")))
