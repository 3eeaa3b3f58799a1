"""People counted by the thing each moves ("three prams are pushed to the food court", "two
wheelchairs roll in"): a pram or a wheelchair goes nowhere alone, so each is a person, labelled by
who goes with it (a parent pushing a pram, a wheelchair user), not a group named "pram"."""

from __future__ import annotations

# A thing a person moves with -> the label of the person it counts.
THING_PEOPLE: dict[str, str] = {
    "pram": "parent", "pushchair": "parent", "buggy": "parent", "stroller": "parent",
    "wheelchair": "wheelchair user", "mobility scooter": "scooter user",
}


def person_of_a_thing(noun: str) -> str | None:
    """The label of the person a thing's noun counts, else None."""
    return THING_PEOPLE.get(noun)
