"""A sample of the public edit chains (eval/refine/chains.yaml) with the embedded model, scored as
`python bench/refine_chains.py` scores the whole set: every step's groups as written by hand, and the
groups a follow-up does not touch byte for byte as they were."""

from __future__ import annotations

import os

import pytest

from grove_tui.analysis.refine_chains import load_chains, read_bundle, score_step
from grove_tui.services.session import GroveSession, ScenarioRequest
from helpers.paths import REPO

# The retrieval index is built once per machine; reuse the suite's when it has one.
pytestmark = pytest.mark.usefixtures("shared_index")

CHAINS = REPO / "eval" / "refine" / "chains.yaml"
# One chain in the suite's budget (a generation, then a change and a removal without the model); the
# `long` run adds chains whose follow-ups call the model, over three worlds and presets.
SAMPLE = ("hospital-normal-slow-family",)
LONG_SAMPLE = ("hospital-normal-visitors", "office-queuing-coffee", "station-queuing-tickets",
               "residential-emergency-smoke")


def run_chains(ids, tmp_path):
    chains = {c.id: c for c in load_chains(CHAINS)}
    results = []
    with GroveSession() as session:
        for chain_id in ids:
            chain = chains[chain_id]
            world = session.load_world(chain.world)
            max_vel = session.load_preset(chain.preset).max_vel
            previous = matched = generated = None
            for number, step in enumerate(chain.steps):
                target = tmp_path / chain.id / str(number)
                if number == 0:
                    generated = session.generate(ScenarioRequest(chain.world, chain.preset, step.say, chain.seed),
                                                 target)
                else:
                    generated = session.refine(generated, step.say, target)
                bundle = read_bundle(target, world, max_vel)
                result, found = score_step(chain, number, bundle, world, previous, matched)
                results.append(result)
                previous, matched = bundle, found
    return results


def check(results):
    wrong = [f"{r.chain} step {r.step} ({r.say}): {r.problems + r.untouched_problems}" for r in results
             if not r.ok or r.untouched_problems]
    assert not wrong, "\n".join(wrong)
    assert sum(r.untouched for r in results) > 0  # the sample has untouched groups to compare


@pytest.mark.slow
def test_a_chain_with_the_embedded_model(tmp_path):
    check(run_chains(SAMPLE, tmp_path))


@pytest.mark.slow
@pytest.mark.long
def test_chains_whose_follow_ups_call_the_model(tmp_path):
    check(run_chains(LONG_SAMPLE, tmp_path))
