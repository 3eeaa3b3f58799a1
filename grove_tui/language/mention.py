"""The output of pass 2: a mention of people (language/mentions.py finds them, language/collectives.py
builds those on a collective noun), before its count is settled and its clause read."""

from __future__ import annotations

from dataclasses import dataclass

from grove_tui.language.model import Count
from grove_tui.language.place_phrases import Place


@dataclass
class Mention:
    """A person phrase that starts a group."""

    first: int  # word span of the person phrase
    last: int
    who: str
    label: str
    count: Count | None  # None for whole-zone and rest-of-parent counts, settled once places are known
    relation: str | None = None
    together: bool = False
    whole_zone: bool = False
    exclusive: bool = False
    rest_of_parent: bool = False
    collective: str | None = None  # the collective noun of "a queue of eight people", "a family"
    exception_of: int | None = None  # "everyone ... except two guards": the mention they are excepted from
    fraction: float = 1.0  # "half the office": the share of the zone's people
    zone_place: Place | None = None  # the zone named inside the mention ("half the open office")
    apposition: tuple[int, int] | None = None  # "everyone in the café, some thirty of them,": the count's words
    robot_object: str | None = None  # "led": the robot escorts them; "followed": the robot follows them
    whole: Mention | None = None  # "two of the six developers": the group named inside, added before this part
    partitive: bool = False  # the group named inside a part ("the six developers"): stays where it is said to be
    fronted: bool = False  # a whole said before its part ("Of the thirty people at the fountain, five ..."): its
    #                        words run to the comma
