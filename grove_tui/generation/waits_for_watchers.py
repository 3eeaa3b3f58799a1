"""The robot waits at its start until the people who are to react as it passes them are in place.

"Six patients queue at the pharmacy and look at the robot as it passes": the patients walk to the
counter first and the robot set off at t = 0, so it passed the head of the queue while the last of them
were still walking there (in place at 24 s, the robot gone by 20 s) and the look "as it passes" could not
happen for them: the report said ✗, truly, of a scenario that did not do what was asked. A robot whose
passing is the moment of a reaction now holds at its start (a stop at the path's first point) for as long
as those people need to reach their places less the time it needs to reach them, and a margin.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np

from grove_tui.generation.postprocess import PostProcessed
from grove_tui.language.model import PromptReading
from grove_tui.scenario.model import RobotSpec

WALK_DETOUR = 1.3  # a walked path is about this much longer than the straight line (doors, furniture)
MARGIN = 4.0  # seconds after the last of them is in place before the robot comes by
LONGEST_HOLD = 60.0
# The robot is near people at a place once its path comes this close to the place: a queue reaches back from
# its counter, and a look "as it passes" is checked from a few metres out.
COMES_NEAR = 10.0  # never hold the robot longer: a run must still show the passing


def held_for_watchers(post: PostProcessed, robot: RobotSpec, reading: PromptReading | None) -> RobotSpec:
    """`robot` with a hold at its start when people with a routine react as it passes them (module doc)."""
    if reading is None or robot.task != "cross" or robot.stops or len(robot.path) < 2:
        return robot
    watching = {g.index for g in post.groups
                if not g.reacts_only and g.reading_index is not None and g.reading_index < len(reading.groups)
                and reading.groups[g.reading_index].robot_interaction is not None
                and reading.groups[g.reading_index].reacts_as_robot_passes}
    if not watching:
        return robot
    path = np.asarray(robot.path, dtype=float).reshape(-1, 2)
    arcs = np.concatenate([[0.0], np.cumsum(np.hypot(*np.diff(path, axis=0).T))])
    hold = 0.0
    for a in post.agents:
        if a.group_index not in watching or not a.targets:
            continue
        place = a.targets[-1][1]
        walk = sum(math.dist(p, q) for p, q in zip([a.start, *[t[1] for t in a.targets]], [t[1] for t in a.targets]))
        in_place = WALK_DETOUR * walk / max(a.max_vel, 0.3)
        near = np.flatnonzero(np.hypot(path[:, 0] - place[0], path[:, 1] - place[1]) <= COMES_NEAR)
        first = int(near[0]) if near.size else int(np.argmin(np.hypot(path[:, 0] - place[0], path[:, 1] - place[1])))
        reaches = float(arcs[first]) / max(robot.max_vel, 0.1)  # when it first comes near their place
        hold = max(hold, in_place + MARGIN - reaches)
    if hold <= 0.5:
        return robot
    start = (float(path[0][0]), float(path[0][1]))
    return replace(robot, stops=((start[0], start[1], round(min(hold, LONGEST_HOLD), 1)),))
