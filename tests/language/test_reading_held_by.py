"""Where a person is held or led "by" (a body part, a piece of clothing) is no place: it is neither
matched nor refused, and the places the sentence does name are still read."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt


@pytest.mark.parametrize("world,prompt,places", [
    ("museum", "A guide leads an old visitor by the elbow from the cloakroom to the café.", {"cloakroom", "cafe"}),
    ("hospital", "A nurse guides an old man by the hand to the pharmacy.", {"pharmacy"}),
    ("mall", "A dad drags his son by the sleeve out of the toy shop.", {"toy_store"}),
    ("station", "A mother holds her toddler by the wrist on platform 2.", {"platform_2"}),
    ("office", "The manager takes a new hire by the arm from reception to the kitchen.", {"reception", "kitchen"}),
])
def test_held_by_a_body_part_or_clothes_is_no_place(worlds, world, prompt, places):
    reading = read_prompt(prompt, worlds[world])
    assert reading.unknown_places == ()
    read = {p for g in reading.groups for p in (g.start, g.destination, g.location) if p}
    assert places <= read, read


@pytest.mark.parametrize("world,prompt,unknown", [
    ("airport", "Two men wait by the fountain near gate A1.", "fountain"),
    ("office", "A cleaner waits by the aquarium in the lobby.", "aquarium"),
])
def test_a_place_after_by_the_world_lacks_is_still_refused(worlds, world, prompt, unknown):
    assert unknown in " ".join(read_prompt(prompt, worlds[world]).unknown_places)
