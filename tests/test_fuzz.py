"""Bounded fuzzing of every parser of user files: worlds, trees, bundles, configs, batch files, HuNavSim
scenarios (`grove import hunav`), and the Gym environment's config and actions.

Any exception that is not a GroveError (or gymnasium's own, for the Gym targets) fails. The budget keeps
the whole file well under a minute in CI; `python bench/fuzz.py --minutes 10` runs the same targets for
longer by hand.
"""

from __future__ import annotations

import pytest
from hypothesis import HealthCheck, given, settings

from helpers.fuzzing import TARGETS, run_target

# Examples per target: the slow targets (a world parse is ~20 ms, an import or a Gym env ~50-100 ms) get fewer.
EXAMPLES = {"world_text": 60, "world_structured": 80, "world_file": 40, "tree": 150, "scenario_dict": 200,
            "scenario_file": 100, "config": 80, "batch": 100, "batch_lines": 100, "hunav_import": 40,
            "hunav_import_text": 40, "gym_config": 40, "gym_action": 60}


@pytest.mark.slow
@pytest.mark.parametrize("name", sorted(TARGETS))
def test_only_grove_errors(name):
    strategy, _ = TARGETS[name]

    @settings(max_examples=EXAMPLES[name], deadline=None, database=None, derandomize=True,
              suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large, HealthCheck.filter_too_much])
    @given(strategy)
    def check(value):
        run_target(name, value)

    check()
