"""Errors of the local model layer, re-exported from grove_tui.errors (where every error lives)."""

from __future__ import annotations

from grove_tui.errors import Cancelled, ModelError

__all__ = ["Cancelled", "ModelError"]
