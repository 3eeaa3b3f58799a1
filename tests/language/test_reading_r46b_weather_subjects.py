"""Weather as a subject ("thunder rumbles overhead", "a gale howls"): nobody, though "thunder" ends
like an agent's noun and may open the sentence capitalised. Language/weather_nouns.py."""

from __future__ import annotations

import pytest


@pytest.mark.parametrize("world,prompt,count", [
    ("zoo", "Thunder rumbles overhead and the thirty or so visitors at the penguin pool run for cover.", 30),
    ("mall", "Thunder cracks overhead as a dozen shoppers hurry in from the car park.", 12),
    ("hospital", "Lightning flashes and the twenty or so patients in the waiting room stay put.", 20),
])
def test_weather_is_nobody(read, world, prompt, count):
    (g,) = read(world, prompt).groups
    assert g.count.value == count
