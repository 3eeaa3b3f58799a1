"""Gas that escapes said by its holder and its sound ("a propane cylinder hisses", "gas is leaking"):
a hazard, so the people who leave or are sent off after it evacuate. A thing that hisses with no gas
named is no hazard. Real spaCy, real worlds."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world, prompt", [
    ("hotel", "The gas main begins hissing behind the kitchen, so the guests in the bar are sent out of the "
              "building."),
    ("museum", "Gas is leaking near the gift shop and the twenty visitors in the great hall leave."),
    ("cookery_school", "A butane canister starts hissing on a hob, so the dozen students in the teaching kitchen leave."),
])
def test_escaping_gas_is_a_hazard(read, world, prompt):
    reading = read(world, prompt)
    assert reading.groups and reading.groups[0].intent == "evacuate"


def test_a_hiss_with_no_gas_is_no_hazard(read):
    reading = read("hotel", "The coffee machine hisses in the bar and the guests in the lobby walk to the restaurant.")
    assert reading.groups and reading.groups[0].intent != "evacuate"
