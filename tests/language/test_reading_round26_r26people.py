"""Round 26 of the reader's people: a plural of a real word no list names ("loaders", "tasters") is
those people, not a misspelt place word one letter away ("leaders", "masters")."""

import pytest


@pytest.mark.parametrize("world,prompt,who", [
    ("parcel_depot", "Four loaders drift over to the canteen.", "Four loaders"),
    ("residential", "Three tasters gather in the kitchen.", "Three tasters"),
    ("courthouse", "Two sawyers wait in the entrance hall.", "Two sawyers"),
    ("ferry_terminal", "Five tasters queue at the café.", "Five tasters"),
])
def test_a_real_plural_is_not_spelt_as_a_place_word(read, world, prompt, who):
    reading = read(world, prompt)
    assert [g.who for g in reading.groups] == [who]
    assert not reading.corrections
