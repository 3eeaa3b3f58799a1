"""The weather is no place (round 45): "stamping their feet against the cold", "sheltering from the rain",
"huddled out of the wind", "standing in the drizzle". The phrase names what the weather does to people,
not where they are, so a world without a "cold" refuses nothing."""

from __future__ import annotations

from grove_tui.language.outing_words import phrase_head
from grove_tui.language.sentence import Sentence

# Head nouns of the weather.
WEATHER_HEADS = frozenset("cold chill heat rain drizzle downpour shower snow sleet hail frost wind gale breeze "
                          "storm fog mist weather sunshine damp wet".split())
_PREPOSITIONS = frozenset({"against", "from", "in", "out", "of", "through", "into"})


def the_weather(s: Sentence, k: int, prep: str) -> bool:
    """Whether the phrase from k, after `prep`, is the weather ("against the cold", "in the rain")."""
    return prep in _PREPOSITIONS and phrase_head(s, k) in WEATHER_HEADS
