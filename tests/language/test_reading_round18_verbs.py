"""Verb, list and chat classes of round 18, with sentences of their own over several worlds (none
from the understanding sets): verbs of going read as waiting or wandering ("make for", "takes her
lunch to", "strolls over to" after another verb, "mooch around"); negated alternatives after them;
chat lists (" n ", "like 40", "brk", groups typed one after the other); placing imperatives ("Post
three guards at X and one more by Y"); kin and apposed counts ("twin toddlers", ", six strong,")."""

from __future__ import annotations

import pytest

# ---- 1. verbs of going: walk there, not wait or wander ----------------------------------------------


@pytest.mark.parametrize("world,prompt,start,destination", [
    ("hospital", "Three porters make for the pharmacy.", None, "pharmacy"),
    ("zoo", "Four visitors make for the gift shop after the talk.", None, "gift_shop"),
    ("hospital", "A nurse takes her lunch to the staff room.", None, "staff_room"),
    ("mall", "Two teenagers take their coffee to the cinema lobby.", None, "cinema_lobby"),
    ("zoo", "A keeper takes her breakfast to the vet room.", None, "vet_room"),
    ("hospital", "A porter steps out of the staff room and strolls over to the pharmacy.", "staff_room", "pharmacy"),
    ("zoo", "A keeper leaves the vet room and wanders over to the penguin beach.", "vet_room", "penguin_beach"),
])
def test_verbs_of_going_walk_to_their_place(read, world, prompt, start, destination):
    g = read(world, prompt).groups[0]
    assert (g.intent, g.start, g.destination) == ("walk", start, destination)


@pytest.mark.parametrize("world,prompt,location", [
    ("hospital", "Five visitors mooch around the entrance lobby.", "entrance_lobby"),
    ("zoo", "Twenty visitors mooch about the children's farm.", "childrens_farm"),
    ("mall", "Some teens mosey around the toy store.", "toy_store"),
    ("hospital", "A nurse takes her lunch in the staff room.", "staff_room"),
])
def test_mooching_wanders_and_lunch_in_a_room_stays(read, world, prompt, location):
    g = read(world, prompt).groups[0]
    assert g.location == location
    assert g.intent == ("wait" if "lunch" in prompt else "wander")


# ---- 3. chat lists: one group per part ------------------------------------------------------------


@pytest.mark.parametrize("world,prompt,first,second", [
    ("warehouse", "8 packers on brk in the canteen n 3 drivers @ dispatch bay", (8, "canteen"), (3, "dispatch_bay")),
    ("warehouse", "like 20 pickers hangin round goods in, 1 manager @ shift office", (20, "goods_in"), (1, "shift_office")),
    ("hospital", "5 nurses on brk in the staff rm n 1 porter @ ward a", (5, "staff_room"), (1, "ward_a")),
    ("hospital", "10 visitors in the cafeteria 3 nurses @ ward a", (10, "cafeteria"), (3, "ward_a")),
    ("zoo", "like 30 kids at the penguin beach, 2 keepers @ reptile hse", (30, "penguin_beach"), (2, "reptile_house")),
])
def test_chat_lists_give_one_group_per_part(read, world, prompt, first, second):
    groups = read(world, prompt).groups
    assert [(g.count.value, g.location) for g in groups] == [first, second]
    assert groups[0].count.kind == ("approximate" if "like" in prompt else "exact")


# ---- 5. kin and apposed counts ---------------------------------------------------------------------


@pytest.mark.parametrize("world,prompt,value", [
    ("warehouse", "Twin toddlers wait in reception.", 2),
    ("office", "Near the kitchen, the twin interns chat.", 2),
    ("warehouse", "The triplets wait in the canteen.", 3),
    ("office", "Triplets play in the boardroom.", 3),
    ("warehouse", "The night shift, six strong, file out of the canteen into the locker room.", 6),
    ("office", "The sales team, eight-strong, walk from reception to the boardroom.", 8),
])
def test_kin_words_and_apposed_strength_give_the_count(read, world, prompt, value):
    groups = read(world, prompt).groups
    assert len(groups) == 1 and groups[0].count.value == value


# ---- 4. an imperative's second group -----------------------------------------------------------------


@pytest.mark.parametrize("world,prompt,first,second", [
    ("warehouse", "Post three guards at reception and one more by the locker room.",
     (3, "reception"), (1, "locker_room")),
    ("warehouse", "Station a trio of guards at reception and two more at the dispatch bay.",
     (3, "reception"), (2, "dispatch_bay")),
    ("hospital", "Post a pair of porters at the entrance lobby and one more by the pharmacy.",
     (2, "entrance_lobby"), (1, "pharmacy")),
    ("hospital", "Station four security guards in the cafeteria and two more at the pharmacy.",
     (4, "cafeteria"), (2, "pharmacy")),
])
def test_a_placing_imperative_gives_both_groups(read, world, prompt, first, second):
    groups = read(world, prompt).groups
    assert [(g.count.value, g.location) for g in groups] == [first, second]


# ---- 2. negated alternatives: the first place is where they go ------------------------------------


@pytest.mark.parametrize("world,prompt,destination", [
    ("zoo", "Nine children make for the penguin beach, not the reptile house, which is shut.", "penguin_beach"),
    ("zoo", "A keeper takes her lunch to the cafe rather than the keepers yard.", "cafe"),
    ("hospital", "Eight visitors make for the cafeteria, not ward c, which is closed.", "cafeteria"),
    ("hospital", "Two nurses make for the staff room instead of the cafeteria.", "staff_room"),
])
def test_a_negated_alternative_is_not_where_they_go(read, world, prompt, destination):
    reading = read(world, prompt)
    g = reading.groups[0]
    assert len(reading.groups) == 1 and (g.intent, g.destination) == ("walk", destination)
    assert reading.unknown_places == ()
