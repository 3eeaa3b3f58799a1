"""Place classes of round 35, each with sentences of its own over at least two worlds (none from the
understanding sets): a fixture people use, take up or look at, said with the room it stands in ("hog
the claw machines in the arcade"), is where they are, the room only says where it is; a tier or storey
of a building ("the upper circle", "the top floor") is a kind of place, refused where the world has
none."""

from __future__ import annotations

import pytest


# ---- 1. a fixture people use or look at, said with its room: the fixture -----------------------------

@pytest.mark.parametrize("world,prompt,location", [
    ("bowling_alley", "Two teenagers hog the claw machines in the arcade.", "claw_machines"),
    ("bowling_alley", "Four mates commandeer the high tables in the sports bar.", "high_tables"),
    ("art_gallery", "Two students sketch the altarpiece in the old masters gallery.", "altarpiece"),
    ("art_gallery", "A painter copies the water lilies in the impressionist gallery.", "water_lilies"),
    ("museum", "Three children sketch the whale skeleton in the great hall.", "whale_skeleton"),
    ("station", "Two commuters hog the ticket machines in the ticket hall.", "ticket_machines"),
    ("station", "A guard mans the ticket machines in the ticket hall.", "ticket_machines"),
])
def test_a_fixture_used_or_looked_at_in_its_room_is_where_they_are(read, world, prompt, location):
    (g,) = read(world, prompt).groups
    assert g.location == location


@pytest.mark.parametrize("world,prompt,location", [
    ("station", "A barista wipes the tables in the cafe.", "cafe"),
    ("hotel", "A waiter polishes the tables in the restaurant.", "restaurant"),
    ("station", "A cleaner polishes the sinks in the toilets.", "toilets"),
    ("bowling_alley", "Two kids play on the air hockey table.", "air_hockey"),
    ("office", "Three engineers hog the printer in the kitchen.", "printer"),
])
def test_a_chore_in_a_room_and_a_fixture_alone_keep_their_reading(read, world, prompt, location):
    (g,) = read(world, prompt).groups
    assert g.location == location


# ---- 2. a tier or storey of a building: a kind of place, refused where the world has none ----------------

@pytest.mark.parametrize("world,prompt,unknown", [
    ("playhouse", "Two ushers walk from the foyer to the grand circle.", "grand circle"),
    ("playhouse", "A few latecomers dash up to the royal circle.", "royal circle"),
    ("cinema", "Four teenagers head up to the upper circle.", "upper circle"),
    ("hospital", "Two porters walk up to the top floor.", "top floor"),
    ("museum", "A guide takes the lift to the first floor.", "first floor"),
    ("hospital", "Two porters wheel a trolley down to the lower ground floor.", "lower ground floor"),
])
def test_a_tier_or_storey_the_world_lacks_is_refused(read, world, prompt, unknown):
    assert unknown in read(world, prompt).unknown_places


@pytest.mark.parametrize("world,prompt,destination", [
    ("concert_venue", "Two fans head up to the upper circle.", "circle"),
    ("concert_venue", "Two fans walk from the foyer to the circle.", "circle"),
])
def test_a_tier_the_world_has_keeps_its_reading(read, world, prompt, destination):
    r = read(world, prompt)
    assert r.groups[0].destination == destination and r.unknown_places == ()


@pytest.mark.parametrize("world,prompt", [
    ("mall", "A circle of friends chats by the fountain."),
    ("office", "A cleaner mops the floor."),
    ("museum", "Twenty pupils sit on the floor by the whale skeleton."),
    ("hospital", "Two nurses stand in a circle in the waiting room."),
])
def test_a_circle_or_floor_alone_is_no_place_to_refuse(read, world, prompt):
    assert read(world, prompt).unknown_places == ()
