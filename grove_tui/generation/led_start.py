"""People the robot leads start where it picks them up, not where it takes them.

"The robot leads a visitor to the computer lab": the visitor follows the robot, and their sentence's
destination is the lab. Placing followers "in the zone their sentence puts them" put the visitor in
the lab itself, so they "reached" it at the first frame. For a group that follows the robot the
destination is where they are taken (a reach claim checks it); where they are is their start, a place
they are in or go through, else beside the robot's start (planning.place_robot_reactors).
"""

from __future__ import annotations

from grove_tui.language.model import GroupReading


def led_destination(group: GroupReading) -> tuple[str, ...]:
    """The group's destination as a place it may start in: none for people the robot leads there."""
    if group.robot_interaction == "follow" or not group.destination:
        return ()
    return (group.destination,)
