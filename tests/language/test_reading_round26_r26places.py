"""Round 26 of the reader's places: what people want where they wait is their purpose ("wanting a refund"); a bare adverb of place ("sits backstage", "stands rinkside"); a day, a time or a manner after a preposition is no place to refuse
("on a sunny bank holiday Monday", "on foot"); a trade's word after a place preposition is its shop or
practice ("towards the dentist"), refused where the world has none; a thing cleared out of a place
("sweeps popcorn out of screen 4") says where the worker is, not where they start."""

import pytest


@pytest.mark.parametrize("world,prompt", [
    ("zoo", "On a scorching August bank holiday a family walks to the reptile house."),
    ("cinema", "On a wet bank holiday Monday twenty film fans queue at the box office."),
    ("garden_centre", "On a bright May bank holiday Saturday dozens of gardeners browse the plant area."),
    ("supermarket", "On a sunny bank holiday Monday about thirty shoppers queue at the tills."),
    ("ferry_terminal", "Three lorry drivers on foot cross from the bag drop to the cafe."),
    ("ice_rink", "Four kids on skates glide from the rinkside to the cafe."),
])
def test_a_day_or_a_manner_after_a_preposition_is_no_place_to_refuse(read, world, prompt):
    r = read(world, prompt)
    assert not r.unknown_places and r.groups


@pytest.mark.parametrize("world,prompt,unknown", [
    ("gp_surgery", "Two patients drift from the waiting area towards the dentist.", "dentist"),
    ("hospital", "Two visitors walk from the cafe to the dentist.", "dentist"),
    ("mall", "Three teens wander from the fountain to the optician.", "optician"),
    ("mall", "A man pops into the optician.", "optician"),
    ("station", "A commuter heads from platform 1 towards the dentist.", "dentist"),
])
def test_a_trade_names_its_practice_which_the_world_may_lack(read, world, prompt, unknown):
    assert unknown in read(world, prompt).unknown_places


@pytest.mark.parametrize("world,prompt,location", [
    ("cinema", "A cleaner sweeps spilt popcorn out of screen four.", "screen_4"),
    ("garden_centre", "Two staff pull weeds out of the plant area.", "outdoor_plants"),
    ("museum", "A cleaner mops water out of the cafe.", "cafe"),
    ("mall", "A janitor sweeps broken glass out of the food court.", "food_court"),
])
def test_a_thing_cleared_out_of_a_place_says_where_the_worker_is(read, world, prompt, location):
    g = read(world, prompt).groups[0]
    assert g.location == location and g.start is None


@pytest.mark.parametrize("world,prompt,role,place", [
    ("concert_venue", "The singer sits quietly backstage.", "location", "backstage"),
    ("concert_venue", "The drummer heads backstage.", "destination", "backstage"),
    ("ice_rink", "A coach stands rinkside.", "location", "rinkside"),
    ("ice_rink", "Two parents wait nervously rinkside while their kids skate.", "location", "rinkside"),
    ("sports_centre", "A mum sits poolside.", "location", "pool_hall"),
])
def test_a_bare_adverb_of_place_is_where_they_are_or_go(read, world, prompt, role, place):
    g = read(world, prompt).groups[0]
    assert getattr(g, role) == place


@pytest.mark.parametrize("world,prompt,location,purpose", [
    ("vet_hospital", "Two owners wait at reception needing worming tablets.", "reception", "worming tablets"),
    ("station", "Three tourists queue at the ticket office wanting refunds.", "ticket_office", "refunds"),
    ("mall", "A man waits at the information desk seeking directions.", "information_desk", "directions"),
    ("supermarket", "Two shoppers queue at the customer service desk wanting a refund.", "customer_service_desk",
     "refund"),
])
def test_what_people_want_where_they_wait_is_their_purpose(read, world, prompt, location, purpose):
    (g,) = read(world, prompt).groups
    assert g.location == location and g.purpose and purpose in g.purpose


# ---- guards: readings that must not change ---------------------------------------------------------

@pytest.mark.parametrize("world,prompt", [
    ("station", "Two commuters on bikes roll to platform 1."),
    ("hospital", "An old man on crutches limps from the pharmacy to the main entrance."),
    ("mall", "Eight schoolkids in single file walk from the fountain to the food court."),
    ("museum", "On Christmas Eve a guard walks to the cafe."),
    ("hospital", "In the early evening rush hour two nurses walk to the pharmacy."),
])
def test_guard_times_and_manners_already_read(read, world, prompt):
    r = read(world, prompt)
    assert not r.unknown_places and r.groups


@pytest.mark.parametrize("world,prompt,unknown", [
    ("mall", "Four teens on skateboards roll to the bowling alley.", "bowling alley"),
    ("station", "On Monday two commuters walk to the planetarium.", "planetarium"),
    ("zoo", "A keeper walks to the butcher.", "butcher"),
])
def test_guard_places_the_world_lacks_are_still_refused(read, world, prompt, unknown):
    assert unknown in read(world, prompt).unknown_places


@pytest.mark.parametrize("world,prompt,role,place", [
    ("gp_surgery", "The dentist walks from the staff room to the waiting area.", "destination", "waiting_area"),
    ("supermarket", "A shopper walks from aisle 1 to the bakery.", "destination", "bakery"),
    ("museum", "A guard walks out of the cafe.", "start", "cafe"),
    ("station", "A porter carries boxes out of the ticket office to the concourse.", "start", "ticket_office"),
    ("museum", "A guard pulls a drunk out of the cafe.", "start", "cafe"),
    ("station", "A cleaner sweeps rubbish from platform 1.", "location", "platform_1"),
])
def test_guard_trades_and_leaving_places(read, world, prompt, role, place):
    g = read(world, prompt).groups[0]
    assert getattr(g, role) == place


@pytest.mark.parametrize("world,prompt,purpose", [
    ("hospital", "Two visitors walk to the cafe in order to buy coffee.", "to buy coffee"),
    ("museum", "Two kids walk to the gift shop to buy postcards.", "postcards"),
])
def test_guard_purposes_after_to(read, world, prompt, purpose):
    (g,) = read(world, prompt).groups
    assert g.purpose and purpose in g.purpose
