"""The queue for a place: "lined up for the Viper", "queuing for the log flume", "sprint for the Viper
line" (round 23). People who queue for a ride or an attraction stand in its queue zone (a zone whose
kind is a queue line, joined by a door to the place or holding it), not at the place itself; a thing
inside a queue zone (the flume's loading platform) is queued for from that zone. "bound for A2" is
bound for the gate's zone, not a fixture in it."""

from __future__ import annotations

from grove_tui.language.places import PlaceIndex, PlaceMatch
from grove_tui.language.sentence import Sentence
from grove_tui.language.tokens import verb_lemma

# Verbs of standing in a queue whose "for" names what is queued for ("line up for", "queue for").
_QUEUE_VERBS = frozenset({"queue", "line", "wait", "stand"})
# The heads that say the queue itself ("the Viper line", "the flume queue").
_QUEUE_HEADS = frozenset({"line", "queue", "q", "queues", "lines"})


def _is_queue_zone(index: PlaceIndex, zone: str) -> bool:
    entry = index.entry(zone)
    return entry is not None and entry.kind == "zone" and any("queue" in t for t in entry.types | {entry.name})


def queue_of(index: PlaceIndex, zone: str) -> str | None:
    """The one queue zone joined to `zone` by a door (either way), or `zone` itself when it is one."""
    if _is_queue_zone(index, zone):
        return zone
    joined = {z.name for z in index.world.zones for d in z.doors if d.leads_to == zone} | \
        {d.leads_to for z in index.world.zones if z.name == zone for d in z.doors}
    queues = sorted(q for q in joined if _is_queue_zone(index, q))
    return queues[0] if len(queues) == 1 else None


def queued_for(s: Sentence, at: int, end: int) -> bool:
    """Whether the "for" at `at` follows a verb of queueing ("lined up for", "queuing patiently for"),
    or the phrase up to `end` ends in a word for the queue itself ("the Viper line")."""
    if end - 1 > at and s.low[end - 1] in _QUEUE_HEADS:
        return True
    for x in range(at - 1, max(-1, at - 4), -1):
        if s.is_verb(x) or s.w[x].tag.startswith("VB"):
            return verb_lemma(s.low[x]) in _QUEUE_VERBS
    return False


def queue_zone_for(s: Sentence, at: int, end: int, match: PlaceMatch) -> tuple[PlaceMatch, str] | None:
    """The queue zone of the place queued for after the "for" at `at`, with the reason; None otherwise."""
    if at >= s.n or s.low[at] != "for":
        return None
    if not queued_for(s, at, end):
        return None
    queue = queue_of(s.index, match.zone)
    if queue is None or queue == match.name:
        return None
    return (PlaceMatch(queue, "zone", queue, match.score, match.exact), f"queued for {match.name}: its queue, {queue}")
