"""Errors of the local model layer."""

from __future__ import annotations

from grove_tui.errors import GroveError


class ModelError(GroveError):
    """A model file or the model process cannot do what was asked; the message says which and why."""


class GenerationCancelled(GroveError):
    """The caller's cancel event stopped a generation; nothing was produced."""
