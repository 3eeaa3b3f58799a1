"""The words of kinds of place (leaf vocabulary): facilities ("the planetarium", "the sauna room") and
kinds of building or shop ("the supermarket", "the library") that a world may lack, read by
language/place_kinds.py, and by language/spelling.py, which leaves a word that makes one with its
neighbour as written ("the post office" is no "poster office")."""

from __future__ import annotations

from grove_tui.language.sport_kinds import SPORT_KINDS
from grove_tui.language.trade_places import TRADE_PLACES

# Facilities people name by their kind: each is a kind of place of its own, never a word for rooms in
# general ("room", "hall", "area") nor for what a room is for ("music", "stock").
PLACE_KINDS = frozenset("""
planetarium aquarium observatory greenhouse conservatory arboretum zoo aviary vivarium
sauna jacuzzi solarium spa steam_room hot_tub ice_rink rink skatepark skate_park bowling_alley bowling arcade
casino nightclub disco karaoke
chapel church mosque synagogue temple prayer_room multifaith_room
nursery creche crèche playground play_area soft_play
barber barbershop hairdresser salon nail_bar beauty_salon tattoo
bank post_office launderette laundrette laundromat
mortuary morgue maternity_ward maternity labour_ward
music_room game_room art_room art_studio craft_room sewing_room playroom play_room dance_studio dance_hall
recording_studio billiard_room snooker_room trophy_room darkroom screening_room
baby_changing baby_change nappy_change parent_room first_aid lost_property
""".split()) | TRADE_PLACES | SPORT_KINDS
# Kinds of building or shop people name a place by ("the supermarket", "the library", "the gym", round 71): a
# world may be one ("walk into the supermarket" of a supermarket: the building, left to the reader), or
# lack it, when it is refused like a facility, never read by meaning as a loosely similar room (an
# outlet village's avenue of shops is no supermarket, a museum's bookshelves no library).
BUILDING_KINDS = frozenset("""
supermarket hypermarket grocery pharmacy bakery library restaurant bistro gym hotel hostel school college
university museum cinema stadium petrol_station garage swimming_pool toy_shop sweet_shop souvenir_shop pet_shop
""".split())


def makes_a_kind(word: str, before: str, after: str) -> bool:
    """Whether a word and the word before or after it name a kind of place ("post" of "post office")."""
    return f"{word}_{after}" in _ALL or f"{before}_{word}" in _ALL


_ALL = PLACE_KINDS | BUILDING_KINDS
