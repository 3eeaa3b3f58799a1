"""Place classes of round 36, each with sentences of its own over at least two worlds (none from the
understanding sets): a place said by a participle after its head ("the place serving tea and scones")
is read by what is done there, as a "that" clause is; a place matched only by a bare alias that is its
head ("kiosk" of the phone kiosk) is no place of another kind said before the head ("the shoe repair
kiosk"), which the world lacks and is refused."""

from __future__ import annotations

import pytest


# ---- 1. a place said by a participle after its head ------------------------------------------------------

@pytest.mark.parametrize("world,prompt,place", [
    ("mall", "Two teenagers walk from the fountain to the place serving coffee.", "coffee_counter"),
    ("museum", "Five visitors walk from the lobby to the place serving tea and cake.", "cafe"),
    ("station", "A woman walks from the platform to the place selling tickets.", "ticket_office"),
    ("art_gallery", "A couple wander from the shop to the spot serving coffee and cake.", "cafe"),
])
def test_a_place_said_by_a_participle_is_where_it_is_done(read, world, prompt, place):
    (g,) = read(world, prompt).groups
    assert g.destination == place


# ---- 2. another kind of a place matched by its bare head alias -------------------------------------------

@pytest.mark.parametrize("world,prompt,said", [
    ("mall", "A man walks to the shoe repair kiosk.", "shoe repair kiosk"),
    ("diy_store", "Two builders stroll over to the key-cutting kiosk.", "key cutting kiosk"),
    ("mall", "A woman hurries to the watch-repair kiosk.", "watch repair kiosk"),
    ("diy_store", "Three shoppers walk from the entrance to the key-cutting kiosk.", "key cutting kiosk"),
])
def test_another_kind_of_a_bare_alias_head_is_refused(read, world, prompt, said):
    r = read(world, prompt)
    assert said in r.unknown_places
    assert all(g.destination is None for g in r.groups)


# ---- guards ----------------------------------------------------------------------------------------------

@pytest.mark.parametrize("world,prompt,place", [
    ("mall", "A man walks to the phone kiosk.", "phone_kiosk"),
    ("mall", "A man walks to the kiosk.", "phone_kiosk"),
    ("mall", "A man walks to the spot that serves coffee.", "coffee_counter"),
    ("diy_store", "A woman walks to the self-checkout kiosk.", "self_checkouts"),
])
def test_a_place_by_its_own_names_keeps_its_reading(read, world, prompt, place):
    (g,) = read(world, prompt).groups
    assert g.destination == place
