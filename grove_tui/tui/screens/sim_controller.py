"""Runs a Simulation in the worker thread and publishes immutable snapshots for the UI to draw.

The UI never touches the Simulation: it sends commands through a queue and reads `latest`, a
reference the sim thread swaps atomically. The run's counters (metrics.json's numbers, through
`analysis.live_metrics.LiveMetrics`) are measured here too, between steps, on the frames recorded
since the last measure: a snapshot carries the counters of its own instant (or of at most
METRICS_SECONDS of wall time before it while playing), whatever the speed, and paused they are
always the paused instant's. The controller also notices when the run is over (everyone out or
done) and pauses it there. Nothing here imports textual.
"""

from __future__ import annotations

import queue
import threading
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Literal, TypeVar, cast, overload

if TYPE_CHECKING:
    from grove_tui.services.domain import Frame, LiveMetrics, Simulation

    SimCall = Callable[[Simulation], object]  # work that needs the simulation still, run between steps
    Reply = Callable[[object], None]  # gets the call's result, or the exception it raised
    # A command from the UI thread: its name, then its arguments (see SimulationController.send).
    Command = (tuple[Literal["play"]] | tuple[Literal["play"], bool] | tuple[Literal["step"]]
               | tuple[Literal["step"], int] | tuple[Literal["speed"], float] | tuple[Literal["select"], int]
               | tuple[Literal["drive"], float, float] | tuple[Literal["follow_path"]]
               | tuple[Literal["call"], SimCall, Reply])

_T = TypeVar("_T")

SPEEDS = (0.25, 0.5, 1.0, 2.0, 4.0, 8.0)
MAX_SPEED = 0.0  # as fast as the machine steps
DRIVE_HOLD_SECONDS = 0.45  # terminals send no key-up: a drive command lasts until key repeat stops
MAX_CATCH_UP_STEPS = 400
# Wall seconds between two measures of the counters while playing (each reads only the frames since
# the last one); paused, stepped or over, they are measured at once.
METRICS_SECONDS = 0.25
# Between two measures the live metrics are fed every this many steps (at 8x about a measure's worth):
# a fast run's frames are read as it goes, not all on one tick. Every 5 steps cost more than it spread
# (bench/tui_fps.py at load 4-5: 11.2 fps and 5.2x real time at 8x against 14.5 and 6.7 with 40).
METRICS_FEED_STEPS = 40
# Behind the asked speed, wall seconds of stepping between two snapshots: the picture keeps moving (at
# least ~10 frames a second) and the run still gets most of the CPU (each drawn frame costs the UI
# thread tens of milliseconds of the GIL at 500 people).
CATCH_UP_SECONDS = 0.1


@dataclass(frozen=True)
class RunEnd:
    """The run is over: every person is out of the building or done with their tree, at time t."""

    t: float
    agents: int
    out: int

    @property
    def text(self) -> str:
        """'all 40 out at t = 83 s', or 'all 40 done at t = 83 s (12 out)'."""
        when = f"t = {self.t:.0f} s"
        if self.out == self.agents:
            return f"all {self.agents} out at {when}"
        return f"all {self.agents} done at {when}" + (f" ({self.out} out)" if self.out else "")


@dataclass(frozen=True)
class Counters:
    """metrics.json's numbers for the run up to simulation time `t` (frame `step`), or why there are none."""

    t: float
    step: int
    values: dict[str, float] = field(default_factory=dict)
    error: str = ""


@dataclass(frozen=True)
class Snapshot:
    serial: int
    frame: Frame
    selected: int  # agent id whose tree status is attached, -1 for none
    tree_status: tuple[tuple[str, str, str], ...]  # (path, name, status) of the selected agent's nodes
    playing: bool
    speed: float  # MAX_SPEED for as fast as possible
    steps_per_second: float  # simulated seconds per wall second over the last two seconds (the real speed)
    manual_robot: bool
    counters: Counters | None = None
    ended: RunEnd | None = None


class SimulationController:
    def __init__(self, simulation: Simulation, fps: float = 20.0, speed: float = 1.0,
                 metrics: LiveMetrics | None = None, run_until: float = 0.0) -> None:
        self.simulation = simulation
        # the scenario's length (generation/run_length.py): the run does not end before it, so a robot's
        # patrol or a stay the people finished their trees before is still seen out
        self.run_until = run_until
        self.fps = fps
        self.dt = float(getattr(simulation, "dt", 0.05))
        self.speed = speed
        self.playing = False
        self.selected = -1
        self.manual_robot = False
        self.latest: Snapshot | None = None
        self.metrics = metrics  # LiveMetrics (or None: no counters)
        self.counters: Counters | None = None
        self.ended: RunEnd | None = None
        self._commands: queue.SimpleQueue[Command] = queue.SimpleQueue()
        self._wake = threading.Event()
        self._serial = 0
        self._anchor: tuple[float, float] | None = None
        self._drive_until = 0.0
        self._driving = False
        self._step_times: list[tuple[float, int]] = []
        self._steps = 0
        self._measured_steps = -1  # the step count the counters were last measured at
        self._metrics_due = 0.0
        self._fed_steps = 0  # the step count the live metrics were last fed at
        self._metrics_failed = ""

    # commands from the UI thread (thread-safe) ------------------------------------------------------
    @overload
    def send(self, name: Literal["play", "step", "follow_path"], /) -> None: ...
    @overload
    def send(self, name: Literal["play"], playing: bool, /) -> None: ...
    @overload
    def send(self, name: Literal["step", "select"], count_or_agent: int, /) -> None: ...
    @overload
    def send(self, name: Literal["speed"], speed: float, /) -> None: ...
    @overload
    def send(self, name: Literal["drive"], vx: float, vy: float, /) -> None: ...
    @overload
    def send(self, name: Literal["call"], function: Callable[[Simulation], _T],
             reply: Callable[[_T | Exception], None], /) -> None: ...

    def send(self, *command: object) -> None:
        """play [on], step [n], speed x, select agent_id, drive vx vy, follow_path, call function reply."""
        self.send_command(cast("Command", command))  # one of the shapes the overloads above let through

    def send_command(self, command: Command) -> None:
        """`send` with the command as one tuple: ("play",), ("speed", 2.0), ..."""
        self._commands.put(command)
        self._wake.set()

    # the worker thread -----------------------------------------------------------------------------
    def run(self, cancelled: Callable[[], bool]) -> None:
        from grove_tui.cpu import hold_ui_core

        period = 1.0 / self.fps
        self._measure()
        self._publish()
        try:
            self._run(cancelled, period, hold_ui_core)
        finally:
            hold_ui_core(self, False)

    def _run(self, cancelled: Callable[[], bool], period: float, hold_ui_core: Callable[[object, bool], None]) -> None:
        while not cancelled():
            tick_start = time.monotonic()
            changed = self._drain()
            # While the run plays, a model working meanwhile (a new scenario, a replan) leaves one core
            # to the UI and the simulation; while it is paused the model gets every idle core (cpu.py).
            hold_ui_core(self, self.playing)
            if self.playing:
                changed |= self._advance(tick_start, period)
            if self._driving and time.monotonic() > self._drive_until:
                self._robot_command(0.0, 0.0)
                self._driving = False
            if changed:
                self._check_end()
            if self._counters_due():
                self._measure()
                changed = True
            if changed:
                self._publish()
            remaining = period - (time.monotonic() - tick_start)
            if remaining > 0 and self._wake.wait(remaining):
                self._wake.clear()

    def _advance(self, now: float, period: float) -> bool:
        sim = self.simulation
        before = self._steps
        if self.speed == MAX_SPEED:
            deadline = now + period
            while time.monotonic() < deadline:
                sim.step()
                self._steps += 1
                self._measure_frames()
        else:
            t = self._time()
            if self._anchor is None:
                self._anchor = (now, t)
            target = self._anchor[1] + self.speed * (now - self._anchor[0])
            steps = min(int((target - t) / self.dt + 1e-9), MAX_CATCH_UP_STEPS)
            # At most CATCH_UP_SECONDS of stepping between two snapshots: a machine that cannot keep up
            # with the speed runs as fast as it can and the picture keeps moving (400 steps of 500 people
            # in one go held it for a second or two at 8x).
            deadline = now + max(period, CATCH_UP_SECONDS)
            done = 0
            while done < steps and (done == 0 or time.monotonic() < deadline):
                sim.step()
                self._steps += 1
                done += 1
                self._measure_frames()
            if done < steps:
                self._anchor = None  # behind: drop the backlog, the status shows the real speed
        done = self._steps - before
        if done:
            self._step_times.append((time.monotonic(), done))
            cutoff = time.monotonic() - 2.0
            self._step_times = [(ts, n) for ts, n in self._step_times if ts >= cutoff]
        return done > 0

    def _time(self) -> float:
        return float(getattr(self.simulation, "time", None) or self.simulation.frame().t)

    def _check_end(self) -> None:
        """Pause the run where nothing is left to happen to its people (once: play resumes it after)."""
        if self.ended is not None:
            return
        run_state = getattr(self.simulation, "run_state", None)
        if run_state is None:
            return
        state = run_state()
        if state.over and self._time() + 1e-9 >= self.run_until:
            self.ended = RunEnd(self._time(), state.agents, state.out)
            self.playing = False
            self._anchor = None

    def _counters_due(self) -> bool:
        if self.metrics is None or self._measured_steps == self._steps:
            return False
        # Paused (after a step, or at the end): measure now; playing: every METRICS_SECONDS.
        return not self.playing or time.monotonic() >= self._metrics_due

    def _measure_frames(self) -> None:
        """Feed the live metrics the frames recorded since the last feed, every METRICS_FEED_STEPS steps."""
        live = self.metrics
        if live is None or self._metrics_failed or self._steps - self._fed_steps < METRICS_FEED_STEPS:
            return
        self._fed_steps = self._steps
        try:
            live.update(self.simulation.recorder)
        except Exception as exc:  # a metrics bug must show in the panel, not stop the simulation
            self._metrics_failed = f"{type(exc).__name__}: {exc}"

    def _measure(self) -> None:
        """The counters up to now: the live metrics read what is left of the frames since their last read,
        then give metrics.json's numbers."""
        self._measured_steps = self._steps
        self._metrics_due = time.monotonic() + METRICS_SECONDS
        live = self.metrics
        if live is None or (self.counters is not None and self.counters.error):
            return
        sim = self.simulation
        step = int(getattr(sim, "step_count", self._steps))
        try:
            if self._metrics_failed:
                raise RuntimeError(self._metrics_failed)
            live.update(sim.recorder)
            self._fed_steps = self._steps
            values = live.values(sim.events)
        except Exception as exc:  # a metrics bug must show in the panel, not stop the simulation
            self.counters = Counters(self._time(), step, {}, str(exc) if self._metrics_failed else
                                     f"{type(exc).__name__}: {exc}")
            return
        if live.t is not None:
            self.counters = Counters(float(live.t), step, values)

    def _drain(self) -> bool:
        changed = False
        while True:
            try:
                command = self._commands.get_nowait()
            except queue.Empty:
                return changed
            changed = True
            if command[0] == "play":
                self.playing = bool(command[1]) if len(command) > 1 else not self.playing
                self._anchor = None
            elif command[0] == "step":
                self.playing = False
                for _ in range(int(command[1]) if len(command) > 1 else 1):
                    self.simulation.step()
                    self._steps += 1
            elif command[0] == "speed":
                self.speed = float(command[1])
                self._anchor = None
            elif command[0] == "select":
                self.selected = int(command[1])
            elif command[0] == "drive":
                self.manual_robot = True
                self._robot_command(float(command[1]), float(command[2]))
                self._driving = True
                self._drive_until = time.monotonic() + DRIVE_HOLD_SECONDS
            elif command[0] == "follow_path":
                self.manual_robot = False
                self._driving = False
                crowd = getattr(self.simulation, "crowd", None)
                if crowd is not None:
                    crowd.clear_robot_command()
            elif command[0] == "call":
                # Work that needs the simulation still (export) runs here, between steps;
                # `reply` gets the result or the exception (it posts a message to the UI).
                _name, function, reply = command
                try:
                    result = function(self.simulation)
                except Exception as exc:
                    reply(exc)
                else:
                    reply(result)

    def _robot_command(self, vx: float, vy: float) -> None:
        crowd = getattr(self.simulation, "crowd", None)
        if crowd is not None and crowd.has_robot:
            crowd.command_robot(vx, vy)

    def _publish(self) -> None:
        sim = self.simulation
        frame = sim.frame()
        status: tuple[tuple[str, str, str], ...] = ()
        if self.selected >= 0:
            try:
                status = tuple(sim.tree_status(self.selected))
            except Exception:  # the agent left (evacuated) or has no tree: no live status to show
                status = ()
        rate = 0.0
        if len(self._step_times) >= 2:
            span = self._step_times[-1][0] - self._step_times[0][0]
            rate = sum(n for _, n in self._step_times[1:]) / span if span > 0 else 0.0
        self._serial += 1
        self.latest = Snapshot(self._serial, frame, self.selected, status, self.playing, self.speed,
                               rate * self.dt, self.manual_robot, self.counters, self.ended)
