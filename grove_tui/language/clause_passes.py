"""The clause passes over the groups once they are read, in order. Each reads one way English says
what people do or where, which the clause reader leaves to them:

- pacing between two places (pacing_between.py); crowding round a thing after moving (crowding_round.py); a zone cleared in the passive as an
  evacuation from it (cleared_passive.py); steering wide of or hanging back from the robot
  (steered_clear.py); a feeling set apart from its clause (feeling_adjectives.py);
- a purpose that names where people go ("late for boarding at B2": purposed_places.py); going to where
  a problem is (problem_places.py); a place said by what is done there as the room, not a thing in it
  (activity_place_zones.py); a kind of place searched for that the world lacks, refused
  (searched_unknown.py), or a room searched for by a name the world lacks (the same);
- breaking off to do something at a place ("break off to restock from the shelving": broken_off.py);
  an animal led along, no person (led_animals.py);
  walking an animal in a place, wandering there ("walking dogs in the paddock": walked_animals.py);
- a purpose with its place said after going off ("for a cuppa in the canteen": leisure_places.py); an
  errand with a thing carried from one place to another (carried_errands.py), or gathered at one and
  dropped at another (gathered_and_dropped.py); surprise at seeing the
  robot somewhere, said after a comma, whose occasion ("at a gig") is no place (surprised_at.py);
- going off to hide after seeing the robot, an avoidance (robot_hiding.py); a step back or aside from the
  robot where one stands, located there (stepped_aside.py); coming up to the robot in anger, Threatening
  (angry_approach.py); a fright fronted with the robot's clause, avoiding it (fronted_fright_clauses.py).
"""

from __future__ import annotations

from dataclasses import replace

from grove_tui.language.activity_place_zones import activity_place_zones
from grove_tui.language.angry_approach import angry_approach
from grove_tui.language.broken_off import broken_off
from grove_tui.language.carried_errands import carried_errands
from grove_tui.language.coming_over import coming_over_after_seeing
from grove_tui.language.cleared_passive import cleared_away
from grove_tui.language.crowding_round import crowding_round
from grove_tui.language.gathered_and_dropped import gathered_and_dropped
from grove_tui.language.dogged_steps import dogging_the_robot
from grove_tui.language.feeling_adjectives import coloured_by_feeling
from grove_tui.language.feeling_phrases import feelings_said_outright
from grove_tui.language.fronted_fright_clauses import frightened_by_fronted_clause
from grove_tui.language.fronted_surprise import surprised_when_fronted
from grove_tui.language.fronted_fright_moves import feeling_moves_fronted
from grove_tui.language.answered_alarms import answering_alarms
from grove_tui.language.leisure_places import leisure_places
from grove_tui.language.model import PromptReading
from grove_tui.language.pacing_between import pacing_between
from grove_tui.language.places import PlaceIndex
from grove_tui.language.problem_places import problem_places
from grove_tui.language.purposed_places import purposed_places
from grove_tui.language.queued_movers import queued_movers
from grove_tui.language.robot_hiding import hiding_after_seeing
from grove_tui.language.its_people import its_people
from grove_tui.language.searched_unknown import searched_unknown
from grove_tui.language.stepped_aside import stepped_aside_in_place
from grove_tui.language.steered_clear import steering_clear_of_the_robot
from grove_tui.language.surprised_at import occasions, surprised_at
from grove_tui.language.walked_animals import walked_animals
from grove_tui.language.workplace_people import at_their_workplace
from grove_tui.language.led_animals import led_animals


def with_clause_passes(prompt: str, index: PlaceIndex, reading: PromptReading) -> PromptReading:
    """The reading with the clause passes applied, in the order above."""
    groups = coloured_by_feeling(prompt, steering_clear_of_the_robot(cleared_away(crowding_round(index, pacing_between(index, reading.groups)))))
    groups = activity_place_zones(index, problem_places(prompt, index, purposed_places(index, groups)))
    groups = its_people(prompt, index, queued_movers(index, surprised_at(prompt, gathered_and_dropped(index, carried_errands(index, leisure_places(index, broken_off(index, walked_animals(led_animals(groups)))))))))
    groups = feelings_said_outright(prompt, coming_over_after_seeing(prompt, dogging_the_robot(groups)))
    groups = hiding_after_seeing(groups)  # "sees the robot and scurries off to hide": avoiding it
    groups = surprised_when_fronted(prompt, groups)  # "Startled, the temp leaps back": surprise
    groups = frightened_by_fronted_clause(prompt, groups)  # "Spooked as the robot rolls up, kids scramble off": Scared
    groups = feeling_moves_fronted(prompt, groups)  # "Rattled by the robot, a gent edges off": Scared, avoiding it
    groups = angry_approach(prompt, groups)  # "Red-faced, a dealer storms up to the robot": a threat
    groups = stepped_aside_in_place(groups)  # "an intern at the printer steps back": stays at the printer
    groups = at_their_workplace(index, groups)  # "the cloakroom attendant hangs up coats": at the cloakroom
    groups = answering_alarms(index, groups)  # "hearing the alarm, a lifeguard hurries to first aid": walks
    unknown = tuple(dict.fromkeys((*reading.unknown_places, *searched_unknown(prompt, index))))
    events = occasions(prompt)
    unknown = tuple(u for u in unknown if not set(u.lower().split()[-1:]) & events)
    return replace(reading, groups=groups, unknown_places=unknown)
