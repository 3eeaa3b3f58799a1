"""The domain types the façade hands a front end, named here so the app can annotate with them.

GroveSession's calls take and give a World, a Simulation and its Frames, the live metrics and grounding
checker a run feeds, the velocity fields a scenario carries and a follow-up's Refinement. The app may not
import the packages that define them (the layers contract in pyproject.toml: the front ends reach the
pipeline only through services), so it imports their names from here, under TYPE_CHECKING: types for
mypy, no import at run time. The scenario contract (grove_tui/scenario) the app reads directly.
"""

from __future__ import annotations

from grove_tui.analysis.live_metrics import LiveMetrics
from grove_tui.analysis.outcomes import OutcomeChecker
from grove_tui.generation.refine import Refinement
from grove_tui.navigation.velocity_field import VelocityField
from grove_tui.simulation.simulation import Frame, Simulation
from grove_tui.world import World, Zone

__all__ = ["Frame", "LiveMetrics", "OutcomeChecker", "Refinement", "Simulation", "VelocityField", "World", "Zone"]
