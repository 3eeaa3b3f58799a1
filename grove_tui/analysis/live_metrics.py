"""metrics.json's numbers for a run while it runs, at the cost of the frames since the last look.

`grove metrics` streams trajectories.csv through the accumulators of `metrics.py` and
`hunav2_metrics.py` a block of frames at a time (`bundle_metrics`). `LiveMetrics` feeds the same
accumulators the recorder's new rows as the simulation makes them, rounded as trajectories.csv
stores them, so the app's counters are metrics.json's numbers for the run so far without
recomputing the run each time (which grew with the run: 4.8 s of CPU at t = 21 s with 500 people).

    live = LiveMetrics(scenario, world)
    live.update(simulation.recorder)           # in the simulation's thread, between steps
    live.values(simulation.events)             # {"agent_overlaps": 3.0, "goal_reach_rate": 0.5, ...}
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Protocol

import numpy as np

from grove_tui.analysis.bundle_metrics import _hunav2_accumulator, metrics_options
from grove_tui.analysis.metrics import ROBOT_ID, CrowdAccumulator, MetricsReport, RobotAccumulator, Trajectories
from grove_tui.crowd.recording import CSV_COLUMNS
from grove_tui.scenario.events import SimEvent
from grove_tui.scenario.model import Scenario

if TYPE_CHECKING:
    from grove_tui.analysis.hunav2_metrics import Hunav2Accumulator
    from grove_tui.world.model import World


class RowSource(Protocol):
    """What LiveMetrics reads: a trajectory recorder (crowd.recording.TrajectoryRecorder)."""

    @property
    def recorded_rows(self) -> int: ...

    def rows_from(self, start: int) -> np.ndarray: ...


def rows_table(rows: np.ndarray) -> np.ndarray:
    """Recorder rows (structured) as the (R, 9) table trajectories.csv holds: t, x, y, vx, vy and yaw
    rounded to its four decimals, so live numbers and `grove metrics` of the exported run agree."""
    table = np.column_stack([np.asarray(rows[name], dtype=np.float64) for name in CSV_COLUMNS])
    table[:, 1] = np.round(table[:, 1], 4)
    table[:, 3:8] = np.round(table[:, 3:8], 4)
    return table


class LiveMetrics:
    """The run's metrics, fed whole frames in order (every call reads the rows recorded since the last)."""

    def __init__(self, scenario: Scenario, world: World) -> None:
        self.scenario = scenario
        self.world = world
        self._options = metrics_options(scenario, world, ())
        self._ids: np.ndarray | None = None
        self._robot: RobotAccumulator | None = None
        self._crowd: CrowdAccumulator | None = None
        self._hunav2: Hunav2Accumulator | None = None
        self.rows = 0  # recorder rows consumed
        self.t: float | None = None  # time of the last frame consumed
        self.frames = 0

    def _start(self, ids: np.ndarray) -> None:
        options = self._options
        self._ids = ids
        self._robot = RobotAccumulator(ids, robot_radius=options["robot_radius"], person_radius=options["person_radius"],
                                       goal=options["robot_goal"], walls=options["walls"], groups=options["groups"])
        self._crowd = CrowdAccumulator(ids, walls=options["walls"], final_goals=options["final_goals"],
                                       walkable_area=options["walkable_area"], radius=options["person_radius"])
        self._hunav2 = _hunav2_accumulator(self.scenario, self.world, ids.size)
        self.rows, self.t, self.frames = 0, None, 0

    def update(self, recorder: RowSource) -> bool:
        """Consume the rows recorded since the last call; whether there were any."""
        if recorder.recorded_rows <= self.rows:
            return False
        table = rows_table(recorder.rows_from(self.rows))
        people = np.unique(table[table[:, 2] != ROBOT_ID, 2].astype(np.int64))
        if self._ids is None:
            # People are on the id axis from the first frame: nobody joins a run later.
            self._start(people)
        elif not np.isin(people, self._ids).all():
            # Someone appeared after the first frame: the axis changes, so measure the whole run again.
            self._start(np.union1d(self._ids, people))
            table = rows_table(recorder.rows_from(0))
        assert self._ids is not None and self._robot is not None and self._crowd is not None and self._hunav2 is not None
        chunk = Trajectories.from_rows_on(table, self._ids, np.full(self._ids.size, -1, dtype=np.int64))
        self._robot.add(chunk)
        self._crowd.add(chunk)
        self._hunav2.add(chunk)
        self.rows = recorder.recorded_rows
        self.t = float(table[-1, 1])
        self.frames += chunk.frames
        return True

    def report(self, events: Sequence[SimEvent]) -> MetricsReport | None:
        """metrics.json's report of the rows consumed so far (None before the first frame)."""
        if self._robot is None or self._crowd is None or self._hunav2 is None or self.frames == 0:
            return None
        self._crowd.events = list(events)
        report = MetricsReport(robot=self._robot.result(), crowd=self._crowd.result())
        report.robot.update(self._hunav2.result())
        return report

    def values(self, events: Sequence[SimEvent]) -> dict[str, float]:
        """The report flat, as the app lists it ({} before the first frame)."""
        report = self.report(events)
        flat: dict[str, float] = {}
        if report is not None:
            for section in report.to_dict().values():
                flat.update(section)
        return flat
