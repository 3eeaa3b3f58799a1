"""Round 29 of the reader's people: a fronted whole's part said with a word for a group of a size
("Of the twelve in X, a trio ...") is so many of them; a person named by the collective they belong to
("the night shift boss") is one group; children named without a person noun ("the little one", "the
Hendersons' youngest") are people, and taken along when led; counted loads someone has with them
("with two crates of milk") are no group."""

import pytest


@pytest.mark.parametrize("world,prompt,whole,part", [
    ("hospital", "Of the twelve folk in the waiting room, a trio are called through to radiology.", 12, 3),
    ("mall", "Out of the ten shoppers at the fountain, a foursome head off to the food court.", 10, 4),
    ("mall", "Of the twenty sat in the food court, a quartet get up and walk to the fountain.", 20, 4),
    ("youth_hostel", "Of the eight hikers in the common room, a trio sneak off to the hobs.", 8, 3),
    ("dental_clinic", "Of the nine patients in the waiting room, a duo walk to reception.", 9, 2),
])
def test_a_fronted_wholes_part_said_as_a_trio(read, world, prompt, whole, part):
    groups = read(world, prompt).groups
    assert [g.count.value for g in groups] == [whole, part]
    assert groups[1].relation == "subset_of:0"


@pytest.mark.parametrize("world,prompt,count", [
    ("hospital", "The night shift porter walks from the ward to the cafeteria.", 1),
    ("warehouse", "The cleaning crew supervisor walks to the loading bay.", 1),
    ("community_centre", "The youth club leader walks to the main hall.", 1),
    ("community_centre", "Two youth club volunteers walk to the main hall.", 2),
    ("office", "The day shift manager walks from the kitchen to the meeting room.", 1),
])
def test_a_person_named_by_their_collective_is_one_group(read, world, prompt, count):
    (group,) = read(world, prompt).groups
    assert group.count.value == count


@pytest.mark.parametrize("world,prompt", [
    ("residential", "Grandad leads the little one by the hand from the kids' room to the bathroom."),
    ("hospital", "A nurse walks the wee ones to the cafeteria."),
    ("mall", "Mum takes her eldest to the fountain."),
    ("hospital", "A porter leads the little one from the ward to the cafeteria."),
    ("museum", "A guide takes the young ones to the main hall."),
])
def test_a_little_one_led_along_is_taken_along(read, world, prompt):
    groups = read(world, prompt).groups
    assert len(groups) == 2 and groups[1].intent == "follow" and groups[1].follows == groups[0].who


@pytest.mark.parametrize("world,prompt", [
    ("hospital", "The Smiths' eldest walks to the cafeteria."),
    ("mall", "The Patels' youngest walks to the food court."),
    ("museum", "The Browns' eldest walks to the main hall."),
    ("residential", "The Hendersons' youngest walks to the bathroom."),
])
def test_a_familys_youngest_is_one_person(read, world, prompt):
    (group,) = read(world, prompt).groups
    assert group.count.value == 1 and group.count.kind == "exact"


@pytest.mark.parametrize("world,prompt", [
    ("care_home", "A delivery driver with two crates of milk hangs about by the noticeboard."),
    ("mall", "A courier with four sacks walks to the fountain."),
    ("hospital", "A porter with three cages of linen waits by the lifts."),
    ("mall", "A cleaner with two buckets waits at the fountain."),
    ("warehouse", "A picker with six cartons of soap walks to the loading bay."),
])
def test_counted_loads_carried_are_no_group(read, world, prompt):
    (group,) = read(world, prompt).groups
    assert group.count.value == 1


@pytest.mark.parametrize("world,prompt,counts", [
    ("mall", "A mum with two kids walks to the fountain.", [1, 2]),
    ("mall", "A teacher with thirty Brownies walks to the fountain.", [1, 30]),
    ("mall", "A trio walk to the fountain.", [3]),
    ("hospital", "Of the twelve patients in the lobby, a pair are called through to radiology.", [12, 2]),
    ("hospital", "The night shift walks from the ward to the cafeteria.", [7]),
    ("hospital", "After the night shift, two nurses walk to the cafeteria.", [2]),
    ("mall", "Mum takes her eldest son to the fountain.", [1, 1]),
    ("hospital", "The shift manager walks to the cafeteria.", [1]),
])
def test_guards_keep_their_reading(read, world, prompt, counts):
    assert [g.count.value for g in read(world, prompt).groups] == counts
