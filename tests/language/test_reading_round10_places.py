"""Place classes of round 10, each with sentences of its own over at least two worlds (none from the
understanding sets): one of a numbered series by its rank ("the second gate", "the last lift"); a kind
of room the world lacks ("the music room", "the games room") is refused, not read as a loosely similar
room; a room-worded phrase is no fixture that shares only a tag with it ("the music corner" is no piano);
"the smoking area" is a part of the building, read or refused, never dropped as the whole scene."""

from __future__ import annotations

import pytest


def place_of(group):
    return group.destination or group.location or group.start


# ---- A. one of a numbered series by its rank --------------------------------------------------------

@pytest.mark.parametrize("world,prompt,place", [
    ("airport", "A family walks to the second gate.", "gate_a2"),
    ("airport", "Two travellers wait at the last gate.", "gate_b2"),
    ("airport", "A pilot walks to the first gate.", "gate_a1"),
    ("hotel", "A guest walks to the third lift.", "lift_3"),
    ("hotel", "A porter waits by the last lift.", "lift_3"),
    ("hospital", "A doctor goes to the last ward.", "ward_c"),
    ("hospital", "A nurse walks to the second examination room.", "exam_room_2"),
    ("office", "A man walks to the second meeting room.", "meeting_room_2"),
    ("office", "A woman sits at the third desk.", "desk_3"),
    ("university", "A professor walks to the last seminar room.", "seminar_room_2"),
    ("library", "Two students sit in the second study room.", "group_study_2"),
])
def test_a_rank_names_that_place_of_a_numbered_series(read, world, prompt, place):
    g = read(world, prompt).groups[0]
    assert place_of(g) == place
    assert not any(c.unsure for c in g.confidence if c.field in ("destination", "location"))


@pytest.mark.parametrize("world,prompt,place", [
    ("station", "Two commuters walk to the first platform.", "platform_1"),  # an alias says the rank
    ("sports_centre", "A medic runs to the first aid room.", "first_aid_room"),  # "first" of a name
])
def test_a_rank_inside_a_name_is_the_name(read, world, prompt, place):
    assert place_of(read(world, prompt).groups[0]) == place


@pytest.mark.parametrize("world,prompt,not_place", [
    ("university", "A student walks to the second lab.", "robotics_lab"),  # no number orders the labs
    ("hospital", "A nurse goes to the fifth ward.", "ward_c"),  # past the end of the series
])
def test_a_rank_no_numbered_series_answers_is_not_forced(read, world, prompt, not_place):
    g = read(world, prompt).groups[0]
    assert place_of(g) != not_place or any(c.unsure for c in g.confidence)


# ---- B. a kind of room the world lacks ------------------------------------------------------------------

@pytest.mark.parametrize("world,prompt,refused", [
    ("hotel", "A man walks to the music room.", "music room"),
    ("library", "A man walks to the music room.", "music room"),
    ("station", "Two kids go to the art room.", "art room"),
    ("office", "A boy runs to the games room.", "games room"),
    ("residential", "A kid runs to the games room.", "games room"),
    ("mall", "Two kids go to the art room.", "art room"),
    ("university", "A girl goes to the dance studio.", "dance studio"),
])
def test_a_kind_of_room_the_world_lacks_is_refused(read, world, prompt, refused):
    r = read(world, prompt)
    assert r.unknown_places == (refused,)
    assert place_of(r.groups[0]) is None


@pytest.mark.parametrize("world,prompt,place", [
    ("sports_centre", "A boy runs to the games room.", "sports_hall"),  # its "games hall"
    ("museum", "Two kids go to the art room.", "modern_art_gallery"),
    ("library", "A student walks to the computer room.", "computer_lab"),
])
def test_a_kind_of_room_the_world_has_is_read(read, world, prompt, place):
    r = read(world, prompt)
    assert r.unknown_places == ()
    assert place_of(r.groups[0]) == place


@pytest.mark.parametrize("world,prompt,refused", [
    ("hotel", "A man waits in the music corner.", "music corner"),  # the piano is only tagged "music"
    ("hotel", "A man sits in the music space.", "music space"),
])
def test_a_room_word_is_no_fixture_sharing_only_a_tag(read, world, prompt, refused):
    r = read(world, prompt)
    assert r.unknown_places == (refused,)


# ---- C. "the X area" is a part of the building -------------------------------------------------------

@pytest.mark.parametrize("world,prompt,refused", [
    ("hotel", "A man waits in the smoking area.", "smoking area"),
    ("station", "A man waits in the smoking area.", "smoking area"),
    ("hotel", "A man walks to the coffee area.", "coffee area"),
])
def test_an_area_the_world_lacks_is_refused_not_dropped(read, world, prompt, refused):
    assert read(world, prompt).unknown_places == (refused,)


@pytest.mark.parametrize("world,prompt,place", [
    ("office", "A candidate waits in the coffee area.", "kitchen"),
    ("hotel", "Two porters wait in the luggage area.", "luggage_room"),
    ("hotel", "Guests relax in the drinks area.", "bar"),
])
def test_an_area_the_world_has_is_read(read, world, prompt, place):
    r = read(world, prompt)
    assert r.unknown_places == ()
    assert place_of(r.groups[0]) == place
