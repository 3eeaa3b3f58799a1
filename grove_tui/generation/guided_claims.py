"""People the robot guides out end where it does, and their claim says so.

"... ten passengers evacuate while the robot leads them to the exit": the guided group's evacuation claim
asked "any exit", so passengers who left by another door than the robot's still read ✓, and the report
never said that the robot and the people it leads end at one place. Planning sends the robot to the exit
the guided group takes (`guided.guided_exit`, the one owner of that place); the group's evacuation claim
then asks for that exit alone, and names it, so a member leaving by another door reads ✗ with the door.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import replace

from grove_tui.scenario.report import GroupGrounding


def guided_out_by(groups: Sequence[GroupGrounding], index: int | None, exit_name: str | None,
                  reading_who: str | None) -> list[GroupGrounding]:
    """`groups` with the guided group's (reading index `index`, phrase `reading_who`) evacuation claim
    asking for `exit_name`, the exit the robot leads them to."""
    if index is None or exit_name is None:
        return list(groups)
    out = []
    for g in groups:
        if g.who == reading_who:
            claims = tuple(replace(c, asked=f"{exit_name}, with the robot that leads them there",
                                   plan=f"{c.plan} to {exit_name}, behind the robot", exits=(exit_name,))
                           if c.kind == "evacuate" else c for c in g.claims)
            g = replace(g, claims=claims)
        out.append(g)
    return out
