"""Every case of eval/suite.yaml, generated with the embedded model and exported for HuNavSim, passes
the emulation of HuNavSim 2.0's loader (parameter names and types, non-empty integer goal lists,
global_goals ids that exist), and every tree loads in BehaviorTree.CPP 4 with exactly HuNavSim's node
IDs and declared ports and reaches a final state that HuNavSim's per-step ticking does not undo.

Slow (one real generation per case, about 40 s each on 2 shared cores).
"""

from __future__ import annotations

from helpers.paths import REPO

import pytest
import yaml
from helpers.hunavsim_factory import HunavSimFactory
from lxml import etree

from grove_tui.analysis.evaluation import load_suite
from grove_tui.bt.hunav_compat import HUNAV_NODES
from grove_tui.exports.hunav import export_hunav
from grove_tui.exports.hunav_loader_check import check_hunav_export
from grove_tui.generation.pipeline import GenerationPipeline
from grove_tui.generation.presets import load_preset
from grove_tui.generation.retrieval import NodeRetriever
from grove_tui.llm.embedded import embedded_model_path
from grove_tui.llm.local import LocalLLM
from grove_tui.scenario.bundle import write_bundle
from grove_tui.world import load_world

pytestmark = pytest.mark.slow
pytest.importorskip("behaviortreepy")

SUITE = REPO / "eval" / "suite.yaml"
CASES = load_suite(SUITE)


@pytest.fixture(scope="module")
def llm():
    model = LocalLLM(embedded_model_path(), role="bt")
    yield model
    model.close()


@pytest.fixture(scope="module")
def retriever():
    return NodeRetriever()


def _spread(cases):
    """The default run exports one emergency case (fields lowered to routes out of the door, the most
    lowering); queues and walks are exported from hand-built bundles in test_export_hunav*.py.
    Every case of the suite with `python -m pytest -m long`."""
    sampled = next(c.id for c in cases if c.preset == "emergency")
    return [pytest.param(c, id=c.id, marks=() if c.id == sampled else pytest.mark.long) for c in cases]


@pytest.mark.parametrize("case", _spread(CASES))
def test_suite_case_export_loads_in_hunavsim(case, llm, retriever, tmp_path):
    pipeline = GenerationPipeline(load_world(case.world), load_preset(case.preset), None, llm, retriever)
    bundle = write_bundle(pipeline.run(case.prompt, seed=case.seed), tmp_path / "bundle")
    export = export_hunav(bundle, tmp_path / "hunav")
    assert check_hunav_export(export.agents_yaml) == []
    params = yaml.safe_load(export.agents_yaml.read_text())["hunav_loader"]["ros__parameters"]
    assert all(params[name]["goals"] for name in params["agents"])
    for path in export.trees:
        factory = HunavSimFactory()
        tree = factory.load(path.read_text())
        statuses, routine = [], []
        for _ in range(400):
            statuses.append(tree.tick_once().name)
            routine.append(sum(n for name, n in factory.ticks.items()
                               if name != "StopAndWaitTimerAction" and HUNAV_NODES[name].category == "action"))
        # the root never completes, so BT.CPP never resets it
        assert set(statuses) == {"RUNNING"}, path.name
        root = etree.fromstring(path.read_bytes())
        loops = [el for el in root.iter("Repeat", "KeepRunningUntilFailure", "RetryUntilSuccessful")
                 if el.get("name") != "hold_final_state"]
        if not loops:  # a routine that does not loop by design ends, and stays ended
            assert routine[-1] == routine[-50], f"{path.name} restarts its routine"
