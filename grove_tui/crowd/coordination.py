"""Objects several agents' trees share: service queues, conversation circles and what was said.

Each agent runs its own tree; when a behavior involves several agents (a queue, a conversation)
their leaves meet here, so the order of a queue or the spot of each speaker has exactly one owner.
"""

from __future__ import annotations

import math
from collections import deque
from collections.abc import Iterator, Sequence
from typing import Protocol

import numpy as np

from grove_tui.bt.runtime.tree_node import SimClock
from grove_tui.world.model import Door, Entity, World, Zone

Point = tuple[float, float]


class FreeSpace(Protocol):
    """Floor a line or a circle may stand on: the simulation's context offers it, and so does the
    formation plan generation draws before any simulation exists (generation/formations.py)."""

    def is_free(self, x: float, y: float) -> bool: ...
    def nearest_free(self, x: float, y: float) -> Point: ...


class Floor(FreeSpace, Protocol):
    """Free floor and the world it belongs to (None: no world, only walls): where a queue line heads."""

    @property
    def world(self) -> World | None: ...


class Bodies(Protocol):
    """The crowd's per-agent arrays the registries read (rows as in grove_tui.crowd.crowd.Crowd)."""

    @property
    def pos(self) -> np.ndarray: ...
    @property
    def radius(self) -> np.ndarray: ...
    @property
    def active(self) -> np.ndarray: ...


class Shared(Floor, Protocol):
    """What the registries read of a running simulation; grove_tui.crowd.context.SimContext provides it
    (a protocol, so the context can own the registries without an import circle)."""

    @property
    def crowd(self) -> Bodies: ...
    @property
    def clock(self) -> SimClock: ...
    @property
    def ids(self) -> Sequence[int]: ...
    def event(self, kind: str, row: int, detail: str = "") -> None: ...

_DIRECTIONS = 48  # candidate headings for a queue line
ARRIVAL_TOLERANCE = 0.3  # metres: an agent within this of its slot/spot has arrived
QUEUE_GRACE = 60.0  # seconds an interrupted member (reacting to the robot) keeps its place in a queue


class ServiceQueue:
    """One line of people at a service point. members[0] is the head (being served)."""

    def __init__(self, name: str, service_point: Point, direction: Point, spacing: float, service_time: float,
                 free_length: float, sim: FreeSpace):
        self.name = name
        self.service_point = service_point
        self.direction = direction
        self.spacing = spacing
        self.service_time = service_time
        self.free_length = free_length
        self.members: list[int] = []  # crowd rows in queue order
        self.pending: list[int] = []  # joined during the current BT tick, ordered at commit()
        self.away: dict[int, float] = {}  # interrupted members -> when they stepped out
        self.head_since: float | None = None  # when the current head started being served
        self.served = 0
        self.aside: list[Point] = []  # where served people went to stand, so the next one stands elsewhere
        self._sim = sim
        self._slots: list[Point] = []

    def slot_point(self, k: int) -> Point:
        """Where the k-th person stands: along the line, pulled into free space beyond its free length."""
        while len(self._slots) <= k:
            j = len(self._slots)
            d = j * self.spacing
            x = self.service_point[0] + self.direction[0] * d
            y = self.service_point[1] + self.direction[1] * d
            if j > 0 and not self._sim.is_free(x, y):
                x, y = self._sim.nearest_free(x, y)
            self._slots.append((x, y))
        return self._slots[k]

    def position_of(self, row: int) -> int | None:
        try:
            return self.members.index(row)
        except ValueError:
            return None

    def tail_point(self) -> Point:
        return self.slot_point(len(self.members))

    def step_out(self, row: int, now: float) -> None:
        """An interrupted member keeps its place for QUEUE_GRACE seconds (see QueueRegistry.commit)."""
        if row in self.members:
            self.away[row] = now
        elif row in self.pending:
            self.pending.remove(row)

    def leave(self, row: int) -> None:
        self.away.pop(row, None)
        if row in self.pending:
            self.pending.remove(row)
        if row in self.members:
            was_head = self.members[0] == row
            self.members.remove(row)
            if was_head:
                self.head_since = None

    def __len__(self) -> int:
        return len(self.members) + len(self.pending)


class QueueRegistry:
    def __init__(self, sim: Shared):
        self._sim = sim
        self.queues: dict[str, ServiceQueue] = {}

    def join(self, name: str, service_point: Point, spacing: float, service_time: float, row: int) -> ServiceQueue:
        queue = self.queues.get(name)
        if queue is None:
            spacing = queue_spacing(spacing, self._sim.crowd.radius)
            direction, free_length = self._line_direction(name, service_point, spacing)
            queue = ServiceQueue(name, service_point, direction, spacing, service_time, free_length, self._sim)
            self.queues[name] = queue
        queue.away.pop(row, None)  # back from an interruption: same place
        if row not in queue.members and row not in queue.pending:
            queue.pending.append(row)
        return queue

    def commit(self) -> None:
        """Agents that joined during the same tick line up nearest-first, so nobody cuts across the line."""
        pos = self._sim.crowd.pos
        now = self._sim.clock.now
        for queue in self.queues.values():
            for row, since in list(queue.away.items()):
                if now - since > QUEUE_GRACE:
                    queue.leave(row)
            if queue.pending:
                tail = queue.tail_point()
                queue.pending.sort(key=lambda r: (pos[r, 0] - tail[0]) ** 2 + (pos[r, 1] - tail[1]) ** 2)
                queue.members.extend(queue.pending)
                queue.pending.clear()

    def in_queue(self) -> int:
        return sum(len(q) for q in self.queues.values())

    def _line_direction(self, name: str, service_point: Point, spacing: float) -> tuple[Point, float]:
        return queue_line_direction(self._sim, name, service_point, spacing)


def queue_spacing(spacing: float, radii: Sequence[float] | np.ndarray) -> float:
    """People do not stand inside each other: a spacing below two radii would only be pushed apart."""
    return max(spacing, 2.0 * float(max(radii)) + 0.1) if len(radii) else spacing


def queue_line_direction(space: Floor, name: str, service_point: Point, spacing: float) -> tuple[Point, float]:
    """Heading of the line: the direction with the most free floor, preferring straight away from the
    served object (a counter's queue extends from its front, not along it).

    `space` has `world` (or None) and `is_free(x, y)`: the running simulation, or the occupancy grid
    when generation predicts where a queue will stand (the robot's planner keeps out of it).
    """
    sx, sy = service_point
    preferred = None
    if space.world is not None:
        try:
            found: Zone | Door | Entity | None = space.world.find(name)
        except Exception:
            found = None
        if isinstance(found, Zone):
            # "queue at security": the zone names the place, the thing served at this point is its
            # entity (a scanner, a counter); the line extends from that thing's front
            found = _served_thing(space.world, service_point) or found
        footprint = getattr(found, "footprint", None)
        if footprint:
            cx = sum(p[0] for p in footprint) / len(footprint)
            cy = sum(p[1] for p in footprint) / len(footprint)
            norm = math.hypot(sx - cx, sy - cy)
            if norm > 1e-6:
                preferred = ((sx - cx) / norm, (sy - cy) / norm)
        normal = getattr(found, "normal", None)
        if preferred is None and normal is not None:
            preferred = (float(normal[0]), float(normal[1]))
    wanted = max(6.0, 12 * spacing)
    step = 0.1
    best, best_score, best_length = (1.0, 0.0), -math.inf, 0.0
    for k in range(_DIRECTIONS):
        a = 2 * math.pi * k / _DIRECTIONS
        ux, uy = math.cos(a), math.sin(a)
        length = 0.0
        d = step
        while d <= wanted:
            if not space.is_free(sx + ux * d, sy + uy * d):
                break
            length = d
            d += step
        score = length
        if preferred is not None:
            score += 1.0 * (ux * preferred[0] + uy * preferred[1])
        if score > best_score + 1e-9:
            best, best_score, best_length = (ux, uy), score, length
    return best, best_length


def _served_thing(world: World, point: Point) -> Entity | None:
    """The entity whose interaction point is `point` (within half a metre), if any."""
    best, best_d = None, 0.5
    for entity in world.entities():
        d = math.dist(entity.interaction_point, point)
        if d <= best_d:
            best, best_d = entity, d
    return best


class Conversation:
    def __init__(self, key: tuple, centre: Point, members: tuple[int, ...], spots: dict[int, Point], now: float):
        self.key = key
        self.centre = centre
        self.members = members
        self.spots = spots
        self.created_at = now
        self.ready: set[int] = set()
        self.started_at: float | None = None
        self.left: set[int] = set()

    @property
    def radius(self) -> float:
        return conversation_radius(len(self.members))


def conversation_radius(n: int) -> float:
    """HuNavSim ConversationFormation: 0.5 m plus 0.2 m per extra participant."""
    return 0.5 + 0.2 * (max(n, 1) - 1)


class ConversationRegistry:
    # Start anyway once this long has passed with at least half the circle in place, so one agent
    # stuck behind an obstacle cannot freeze everyone else forever.
    PATIENCE = 60.0

    def __init__(self, sim: Shared):
        self._sim = sim
        self.conversations: dict[tuple, Conversation] = {}

    def join(self, centre: Point, members: tuple[int, ...], row: int) -> Conversation:
        key = (round(centre[0], 2), round(centre[1], 2), tuple(sorted(members)))
        conv = self.conversations.get(key)
        if conv is None:
            conv = Conversation(key, centre, tuple(sorted(members)), self._assign_spots(centre, members),
                                self._sim.clock.now)
            self.conversations[key] = conv
        conv.left.discard(row)
        return conv

    def mark_ready(self, conv: Conversation, row: int) -> None:
        joining = row not in conv.ready
        conv.ready.add(row)
        if conv.started_at is not None and joining:
            # a late arrival joins a circle already talking
            self._sim.event("conversation_start", row, ",".join(str(self._sim.ids[m]) for m in sorted(conv.ready)))
        if conv.started_at is None:
            active = self._sim.crowd.active
            present = [m for m in conv.members if active[m] and m not in conv.left]
            waited = self._sim.clock.now - conv.created_at
            if all(m in conv.ready for m in present) or (waited >= self.PATIENCE and 2 * len(conv.ready) >= len(present)):
                conv.started_at = self._sim.clock.now
                # Who talks with whom, for the outcome checks: every member in the circle now.
                talking = sorted(conv.ready)
                ids = ",".join(str(self._sim.ids[m]) for m in talking)
                for m in talking:
                    self._sim.event("conversation_start", m, ids)

    def leave(self, conv: Conversation, row: int) -> None:
        if conv.started_at is not None and row not in conv.left:
            self._sim.event("conversation_end", row, "")
        conv.left.add(row)
        conv.ready.discard(row)
        if all(m in conv.left for m in conv.members):
            self.conversations.pop(conv.key, None)

    def _assign_spots(self, centre: Point, members: tuple[int, ...]) -> dict[int, Point]:
        """Spots evenly around the circle, given greedily by distance (closest pair first), as HuNavSim."""
        n = len(members)
        r = conversation_radius(n)
        pos = self._sim.crowd.pos
        cx, cy = centre
        start = math.atan2(float(pos[members[0], 1]) - cy, float(pos[members[0], 0]) - cx) if n else 0.0
        spots = []
        for k in range(n):
            a = start + 2 * math.pi * k / n
            x, y = cx + r * math.cos(a), cy + r * math.sin(a)
            if not self._sim.is_free(x, y):
                x, y = self._sim.nearest_free(x, y)
            spots.append((x, y))
        pairs = sorted(
            ((float(pos[m, 0]) - sx) ** 2 + (float(pos[m, 1]) - sy) ** 2, m, k)
            for m in members for k, (sx, sy) in enumerate(spots)
        )
        assigned: dict[int, Point] = {}
        used: set[int] = set()
        for _, m, k in pairs:
            if m not in assigned and k not in used:
                assigned[m] = spots[k]
                used.add(k)
        return assigned


class SpeechLog:
    """What agents said (SaySomething), for IsAnyoneSpeaking/IsSpeaking and the status line."""

    def __init__(self, keep: int = 512):
        self.entries: deque[tuple[float, int, str]] = deque(maxlen=keep)

    def say(self, t: float, row: int, message: str) -> None:
        self.entries.append((t, row, message))

    def since(self, t: float) -> Iterator[tuple[float, int, str]]:
        for entry in reversed(self.entries):
            if entry[0] < t:
                break
            yield entry
