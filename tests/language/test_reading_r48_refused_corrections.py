"""A real English word is never corrected into another when the place it makes is refused anyway
("the car park" read "cart park", "the cab rank" read "cabin rank"): the correction is taken back and the
sentence read as written (refused_corrections.py). A misspelling is still corrected."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,word", [
    ("hotel", "Two men meet in the car park.", "car"),
    ("blood_donor_centre", "Two men wait by the car wash.", "car"),
    ("botanic_garden", "Two men meet in the car park.", "car"),
    ("hotel", "A driver waits at the cab rank.", "cab"),
])
def test_a_real_word_is_not_corrected_into_a_refusal(read, world, prompt, word):
    r = read(world, prompt)
    assert not any(c.startswith(f"read '{word}'") for c in r.corrections)
    assert not any(p.split()[0] != word and p.endswith(("park", "wash", "rank")) for p in r.unknown_places)


def test_a_misspelling_is_still_corrected(read):
    r = read("hospital", "Two nurses walk to the pharmcy.")
    assert r.corrections
    assert r.groups[0].destination is not None
