"""Place classes of round 33, each with sentences of its own over at least two worlds (none from the
understanding sets): an event or a club named like a place is no place to refuse; a hazard that spreads
into a room is not where the people in it go; a named kind of place the world lacks ("the key-cutting
kiosk") is refused whole, not read as the world's one kiosk."""

from __future__ import annotations

import pytest


# ---- 1. an event or a club named like a place: nothing to refuse -----------------------------------------

@pytest.mark.parametrize("world,prompt", [
    ("community_centre", "Two grannies at the barn dance stop to stare at the robot."),
    ("hospital", "Ten nurses at the leaving party wave at the robot."),
    ("community_centre", "Six neighbours at the jumble sale gawp at the robot."),
    ("mall", "Two girls from the Brownie pack walk to the food court."),
    ("cinema", "Twelve fans at the quiz evening cheer at the robot."),
    ("hospital", "A few porters at the charity raffle stare at the robot."),
    ("library", "Four readers at the coffee morning look at the robot."),
    ("museum", "Eight pensioners at the tea dance wave at the robot."),
    ("cinema", "A girl from the Brownie pack is spellbound by the robot."),
])
def test_an_event_or_a_club_named_like_a_place_is_not_refused(read, world, prompt):
    assert read(world, prompt).unknown_places == ()


@pytest.mark.parametrize("world,prompt", [
    ("community_centre", "Some regulars from the bingo night walk to the kitchen."),
    ("library", "Two pensioners from the knitting circle walk to the reading room."),
    ("cinema", "Ten teenagers from the film club walk to the bar."),
    ("mall", "Three mums from the toddler group walk to the food court."),
])
def test_clubs_read_already_are_still_not_refused(read, world, prompt):
    assert read(world, prompt).unknown_places == ()


@pytest.mark.parametrize("world,prompt,unknown", [
    ("community_centre", "Two grannies walk from the kitchen to the swimming pool.", "swimming pool"),
    ("library", "Two pensioners walk to the night club.", None),
    ("hospital", "Ten nurses walk to the bowling alley.", "bowling alley"),
])
def test_places_the_world_lacks_are_still_refused_beside_events(read, world, prompt, unknown):
    got = read(world, prompt).unknown_places
    assert (unknown in got) if unknown else True


# ---- 2. a hazard that spreads into a room: where the people are, not where they go ----------------------

@pytest.mark.parametrize("world,prompt,start,destination", [
    ("art_gallery", "Smoke drifts into Gallery 3 and the thirty visitors in there leave through the temporary fire exit.",
     "modern_gallery", "temporary_fire_exit"),
    ("cinema", "Smoke drifts into screen 1 and the fifty fans in there are ushered out through the bar's emergency door.",
     "screen_1", "bar_street_door"),
    ("cinema", "Smoke pours into screen 1 and the fifty fans there are led out through the bar street door.",
     "screen_1", "bar_street_door"),
    ("hospital", "Smoke drifts into the cafeteria and the ten visitors in there are ushered out through the main entrance.",
     "cafeteria", "main_entrance"),
    ("hospital", "Water pours into the cafeteria and the ten visitors leave through the main entrance.",
     "cafeteria", "main_entrance"),
    ("hospital", "Smoke spreads to the cafeteria and the ten visitors leave via the main entrance.",
     "cafeteria", "main_entrance"),
])
def test_a_hazard_spreading_into_a_room_is_where_they_start_not_where_they_go(read, world, prompt, start, destination):
    (g,) = read(world, prompt).groups
    assert (g.start, g.destination) == (start, destination)


@pytest.mark.parametrize("world,prompt,start,destination", [
    ("hospital", "Smoke fills the cafeteria and the ten visitors in there are ushered out through the main entrance.",
     "cafeteria", "main_entrance"),
    ("hospital", "Water pours into the cafeteria and the ten visitors walk to the main entrance.",
     None, "main_entrance"),
    ("art_gallery", "The thirty visitors in Gallery 3 leave through the temporary fire exit.",
     "modern_gallery", "temporary_fire_exit"),
])
def test_hazards_read_already_keep_their_reading(read, world, prompt, start, destination):
    (g,) = read(world, prompt).groups
    assert g.destination == destination
    assert start is None or g.start == start


# ---- 3. a named kind of place the world lacks: refused whole, no place of the same head read -------------

@pytest.mark.parametrize("world,prompt,start,refused", [
    ("supermarket", "A man walks from the tills to the key-cutting kiosk.", "checkouts", "key cutting kiosk"),
    ("mall", "A man walks from the food court to the key-cutting kiosk.", "food_court", "key cutting kiosk"),
    ("mall", "Two girls walk from the food court to the nail-painting kiosk.", "food_court", "nail painting kiosk"),
    ("airport", "A man walks from the check-in hall to the key-cutting kiosk.", "check_in_hall", "key cutting kiosk"),
    ("hospital", "A man walks from the lobby to the key-cutting kiosk.", "entrance_lobby", "key cutting kiosk"),
])
def test_a_named_kind_of_place_the_world_lacks_is_refused_whole(read, world, prompt, start, refused):
    r = read(world, prompt)
    (g,) = r.groups
    assert refused in [u.replace("-", " ") for u in r.unknown_places]
    assert (g.start, g.destination, g.via) == (start, None, ())


@pytest.mark.parametrize("world,prompt,destination", [
    ("supermarket", "A man walks from the tills to the lottery kiosk.", "customer_service"),
    ("mall", "A man walks from the food court to the mobile kiosk.", "phone_kiosk"),
    ("mall", "A man walks from the food court to the phone kiosk.", "phone_kiosk"),
    ("post_office", "A man walks from the counter to the passport photo booth.", "photo_booth"),
    ("diy_store", "Two joiners walk from the tills to the paint-mixing desk.", "paint_mixing_desk"),
    ("airport", "Two travellers walk from gate A1 to the first-class lounge.", "airline_lounge"),
])
def test_kinds_of_place_the_world_has_keep_their_reading(read, world, prompt, destination):
    assert read(world, prompt).groups[0].destination == destination
