"""Clause classes of round 13c, each with sentences of its own over at least two worlds (none from the
understanding sets): a means of moving (a way or a vehicle taken, a thing pushed along) is a walk; a
phrasal verb of an activity ("do laps", "stretch their legs"); a verb of motion with "round" past an
adverb is wandering there; pace said by a phrase or negated; stays said as a spell, a unit and a half,
the whole scenario or a part of the day."""

from __future__ import annotations

import pytest

# ---- A. a way taken by its means, the plural too: walking there ------------------------------------


@pytest.mark.parametrize("world,prompt,destination", [
    ("hotel", "Two guests take the lifts.", "lift_lobby"),
    ("hospital", "Three visitors take the elevators.", "elevator_hall"),
    ("hospital", "A porter takes the lifts.", "elevator_hall"),
])
def test_a_means_of_moving_taken_is_walking_to_it(read, world, prompt, destination):
    group = read(world, prompt).groups[0]
    assert (group.intent, group.destination, group.location) == ("walk", destination, None)


# ---- B. a vehicle driven or ridden, a thing pushed along: walking, whatever the place ---------------


@pytest.mark.parametrize("world,prompt", [
    ("warehouse", "A forklift driver drives to bay 4."),
    ("ferry_terminal", "Two lorry drivers drive onto the car deck."),
    ("ferry_terminal", "A cyclist rides onto the car deck."),
    ("hospital", "A porter wheels a bed."),
    ("supermarket", "A shopper pushes a trolley along."),
])
def test_a_vehicle_or_a_thing_pushed_along_is_walking(read, world, prompt):
    assert read(world, prompt).groups[0].intent == "walk"


# ---- C. phrasal verbs of an activity ------------------------------------------------------------------


@pytest.mark.parametrize("world,prompt,intent", [
    ("residential", "A jogger does laps of the garden.", "wander"),
    ("sports_centre", "Swimmers do lengths in the pool.", "wander"),
    ("office", "Two developers stretch their legs in the corridor.", "wander"),
    ("hotel", "A guest stretches his legs in the lobby.", "wander"),
])
def test_a_phrasal_verb_of_an_activity_gives_its_intent(read, world, prompt, intent):
    assert read(world, prompt).groups[0].intent == intent


# ---- D. a verb of motion with "round" (past an adverb) and nowhere to go: wandering there -------------


@pytest.mark.parametrize("world,prompt,location", [
    ("station", "Commuters walk round platform 1.", "platform_1"),
    ("museum", "Visitors walk slowly around the dinosaur hall.", "dinosaur_gallery"),
    ("museum", "A tour group shuffles slowly round the gallery.", "modern_art_gallery"),
])
def test_moving_round_a_place_with_nowhere_to_go_is_wandering_there(read, world, prompt, location):
    group = read(world, prompt).groups[0]
    assert (group.intent, group.location, group.start) == ("wander", location, None)


# ---- E. pace: a phrase of pace; a word of speed negated or only the scenario's "run" ------------------


@pytest.mark.parametrize("world,prompt,pace,intent", [
    ("mall", "An elderly couple walk at a snail's pace to the food court.", "slow", "walk"),
    ("office", "A courier walks at a brisk pace to reception.", "fast", "walk"),
    ("airport", "A pilot walks to gate A1, not rushing.", "normal", "walk"),
    ("hospital", "A doctor walks to the ICU without hurrying.", "normal", "walk"),
    ("office", "Two interns walk to the kitchen in no hurry.", "slow", "walk"),
    ("station", "A busker stays on platform 1 for the rest of the run.", "normal", "wait"),
    ("library", "Students study in the reading room for the whole run.", "normal", "wait"),
])
def test_pace_said_by_a_phrase_or_negated(read, world, prompt, pace, intent):
    group = read(world, prompt).groups[0]
    assert (group.pace, group.intent) == (pace, intent)


# ---- F. stays: a vague spell, a unit and a half, the whole scenario, a part of the day ----------------


@pytest.mark.parametrize("world,prompt,seconds", [
    ("station", "A commuter waits on platform 1 for a bit.", 120.0),
    ("hotel", "A guest sits in the bar for a while.", 600.0),
    ("hospital", "A visitor sits in the waiting room for an hour and a half.", 5400.0),
    ("airport", "A passenger waits at gate A1 for a minute and a half.", 90.0),
    ("mall", "A man waits outside the cinema all afternoon.", 10800.0),
    ("library", "A student reads in the reading room all morning.", 10800.0),
])
def test_a_stay_said_as_a_spell_or_a_part_of_the_day(read, world, prompt, seconds):
    group = read(world, prompt).groups[0]
    assert (group.wait_seconds, group.purpose) == (seconds, None)


@pytest.mark.parametrize("world,prompt", [
    ("station", "A busker stays on platform 1 for the rest of the run."),
    ("museum", "Two guards stand by the entrance for the rest of the scenario."),
    ("hotel", "A guest sits in the bar for the whole time."),
    ("office", "A receptionist sits at reception for the whole simulation."),
])
def test_a_stay_for_the_whole_scenario_is_no_purpose(read, world, prompt):
    group = read(world, prompt).groups[0]
    assert (group.intent, group.wait_seconds, group.purpose) == ("wait", None, None)
