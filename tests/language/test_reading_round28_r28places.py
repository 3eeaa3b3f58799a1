"""Round 28 of the reader's places: a fixture said as another kind of the head the world's one has ("the
petrol kiosk" where the only kiosk is the coffee kiosk) is a place the world lacks; a word alone that
begins the names of a room and of its fixtures names the room ("into departures", "down to xray"); a
bare head that names one place exactly, with a "where" clause that says which of its kind ("the pool
where toddlers have lessons": the teaching pool, not the main pool)."""

import pytest


@pytest.mark.parametrize("world,prompt,unknown", [
    ("service_station", "A bus driver walks from the food court to the petrol kiosk.", "petrol kiosk"),
    ("service_station", "Two lorry drivers walk over to the fuel kiosk.", "fuel kiosk"),
    ("zoo", "A keeper walks from the gift shop to the petrol kiosk.", "petrol kiosk"),
    ("zoo", "Three parents head to the fuel kiosk.", "fuel kiosk"),
])
def test_another_kind_of_the_head_is_a_place_the_world_lacks(read, world, prompt, unknown):
    r = read(world, prompt)
    assert r.groups[0].destination is None and unknown in r.unknown_places


@pytest.mark.parametrize("world,prompt,destination", [
    ("ferry_terminal", "A handful of walkers drift out of the cafe into departures.", "departure_lounge"),
    ("ferry_terminal", "Two cyclists walk from arrivals to departures.", "departure_lounge"),
    ("airport", "A family hurries from the toilets to departures.", "check_in_hall"),
    ("hospital", "A porter wheels a patient from the ward to xray.", "radiology"),
    ("hospital", "A nurse takes a patient round to xray.", "radiology"),
])
def test_a_word_that_begins_a_room_and_its_fixtures_names_the_room(read, world, prompt, destination):
    assert read(world, prompt).groups[0].destination == destination


@pytest.mark.parametrize("world,prompt,destination", [
    ("swimming_baths", "A coach walks from the cafe to the pool where toddlers have lessons.", "teaching_pool"),
    ("swimming_baths", "Two mums carry their babies to the pool where the baby sessions are held.", "teaching_pool"),
    ("aquarium", "Three kids run to the tank where the sharks swim.", "shark_tunnel"),
    ("aquarium", "A keeper walks to the tank where the jellyfish drift.", "jelly_tanks"),
])
def test_a_bare_head_with_a_where_clause_is_the_place_the_clause_says(read, world, prompt, destination):
    assert read(world, prompt).groups[0].destination == destination


# ---- guards: readings that must not change ---------------------------------------------------------

@pytest.mark.parametrize("world,prompt,destination", [
    ("service_station", "A trucker walks to the espresso kiosk.", "coffee_kiosk"),
    ("service_station", "A trucker walks to the coffee stand.", "coffee_kiosk"),
    ("university", "A student goes to the espresso stand.", "coffee_bar"),
    ("stadium", "A fan walks to the pie kiosk.", "pie_kiosk"),
    ("zoo", "A dad walks to the ice cream kiosk.", "ice_cream_kiosk"),
])
def test_the_places_own_kind_or_a_synonym_keeps_the_place(read, world, prompt, destination):
    assert read(world, prompt).groups[0].destination == destination


@pytest.mark.parametrize("world,prompt,destination", [
    ("station", "Three commuters walk to the departures board.", "departure_board"),
    ("hospital", "A technician walks to the x-ray machine.", "xray_machine"),
    ("hospital", "A porter wheels a patient from the ward to x-ray.", "radiology"),
    ("vet_hospital", "A nurse carries a cat to x-ray.", "x_ray_machine"),
    ("cinema", "A couple walk to the box office.", "box_office"),
])
def test_a_fixture_named_in_full_or_by_its_alias_stays(read, world, prompt, destination):
    assert read(world, prompt).groups[0].destination == destination


@pytest.mark.parametrize("world,prompt,destination", [
    ("swimming_baths", "A lifeguard walks to the pool where people swim lengths.", "main_pool"),
    ("museum", "A guide leads a class to the gallery where the mummies are.", "egyptian_gallery"),
    ("zoo", "A family walks to the kiosk where they sell ice creams.", "ice_cream_kiosk"),
    ("library", "A student walks to the desk where you borrow books.", "issue_desk"),
])
def test_a_where_clause_that_agrees_with_the_head_keeps_the_place(read, world, prompt, destination):
    assert read(world, prompt).groups[0].destination == destination


@pytest.mark.parametrize("world,prompt,count,location", [
    ("youth_hostel", "cyclists x2 having brekkie in dining hall, dorm 1 still asleep (3 ppl)", 3, "dorm_1"),
    ("youth_hostel", "2 wardens at reception, kitchen a packed (8 ppl)", 8, "guest_kitchen"),
    ("hospital", "2 nurses at the desk; cafeteria rammed (15 people)", 15, "cafeteria"),
    ("hospital", "ward a: 4 patients in bed, lobby busy (10 ppl)", 10, "entrance_lobby"),
    ("library", "silent study full (12 students), 2 staff at the issue desk", 12, "reading_room"),
])
def test_a_chat_item_that_says_its_place_first_and_counts_in_brackets(read, world, prompt, count, location):
    r = read(world, prompt)
    assert any(g.count.value == count and g.location == location for g in r.groups)


@pytest.mark.parametrize("world,prompt,count,location", [
    ("hospital", "lobby heaving (10 ppl), 2 nurses at the desk", 10, "entrance_lobby"),
    ("office", "kitchen full (6 ppl), 2 devs at their desks", 6, "kitchen"),
    ("hospital", "The school group (25 children) walks to the cafeteria.", 25, None),
])
def test_a_chat_item_that_already_read_its_place_keeps_it(read, world, prompt, count, location):
    r = read(world, prompt)
    assert any(g.count.value == count and g.location == location for g in r.groups)
