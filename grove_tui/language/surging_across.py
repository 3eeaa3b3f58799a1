"""A crowd flowing across a space (issue 29): "two dozen commuters surge across the station hall towards
the barriers", "forty shoppers stream across the food court to the exit", "fans flood across the
forecourt". A verb of a crowd moving as one mass says the crowd fills that space as it moves: the space
crossed is where they are when the sentence starts, not a place on the way. A walker crossing it ("trek
across the concourse to the café") still only passes through."""

from __future__ import annotations

# Verbs of a crowd moving as one mass, in their base form.
CROWD_FLOW_VERBS = frozenset("surge stream flood pour swarm spill flow throng teem cascade".split())


def crosses_from(verb: str, prep: str) -> bool:
    """Whether a place said with `prep` after `verb` is where a crowd flowing across it starts."""
    return prep == "across" and verb in CROWD_FLOW_VERBS
