"""A role said with the noun "lead" ("the site lead", "the tech lead", "a team lead") is one person,
the leader; "the team lead the visitors" is still the team leading them (language/role_leads.py)."""

from __future__ import annotations

import pytest

CASES = [
    ("hospital", "The team lead walks from reception to the pharmacy.", "pharmacy", None),
    ("mall", "The site lead waits at the food court.", None, "food_court"),
    ("office", "At nine the tech lead strolls to the boardroom.", "boardroom", None),
]


@pytest.mark.parametrize("world,prompt,destination,location", CASES)
def test_the_lead_is_one_person(read, world, prompt, destination, location):
    (lead,) = read(world, prompt).groups
    assert lead.label.endswith("leader") and (lead.count.kind, lead.count.value) == ("exact", 1)
    assert (lead.destination, lead.location) == (destination, location)


def test_a_team_that_leads_people_is_still_the_team(read):
    team, visitors = read("hospital", "The team lead the visitors to the pharmacy.").groups
    assert team.label == "team" and visitors.intent == "follow"
