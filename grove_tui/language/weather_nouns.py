"""Weather and sky words ("thunder rumbles overhead", "the rain hammers down", "a gale blows"): the
subject of a verb, none is a person, though "thunder" ends like an agent's noun ("-er") and a
sentence may start with one, capitalised like a name. A crowd simulation places nobody for them."""

from __future__ import annotations

WEATHER_NOUNS = frozenset("""thunder thunderstorm thunderclap lightning rain rainfall drizzle downpour shower hail
    hailstorm sleet snow snowfall blizzard storm gale wind breeze gust fog mist sunshine sun cloud clouds
    sky weather heatwave cloudburst squall tempest monsoon frost""".split())


def weather_noun(lem: str) -> bool:
    """Whether a lemma names weather or the sky, nobody."""
    return lem in WEATHER_NOUNS
