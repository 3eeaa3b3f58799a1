"""Robot classes of round 12, each with sentences of its own over at least two worlds (none from the
understanding sets): talking to the robot is coming to it; hostile acts on it block it; a word inside a
compound or a place's name is no act on the robot; the robot's serving where it stands is a wait there;
the robot taking people out goes to an exit."""

from __future__ import annotations

import pytest


# ---- A. talking to the robot is approaching it -----------------------------------------------------

@pytest.mark.parametrize("world,prompt", [
    ("hotel", "The robot stops by the lobby. Two tourists ask it for directions."),
    ("hotel", "Guests chat with the robot near reception."),
    ("hospital", "An old man asks the robot the way to the pharmacy."),
    ("library", "The robot waits by the main entrance and a student talks to it."),
    ("museum", "Three children speak to the robot in the lobby."),
    ("airport", "A pilot thanks the robot at the information desk."),
])
def test_talking_to_the_robot_is_approaching_it(read, world, prompt):
    assert read(world, prompt).groups[0].robot_interaction == "approach"


@pytest.mark.parametrize("world,prompt", [
    ("airport", "A pilot asks the robot to fetch a trolley."),
    ("hotel", "Two grandmothers chat on the lobby sofas while the robot patrols the bar."),
    ("station", "Commuters talk about the weather as the robot crosses the concourse."),
])
def test_speaking_not_to_the_robot_is_no_reaction(read, world, prompt):
    assert read(world, prompt).groups[0].robot_interaction is None


# ---- B. hostile acts on the robot block it -----------------------------------------------------------

@pytest.mark.parametrize("world,prompt", [
    ("hotel", "A guest tries to trip the robot in the bar."),
    ("mall", "A teenager tries to push it over as the robot passes the food court."),
    ("warehouse", "An angry worker tries to sabotage the robot."),
    ("station", "A man smashes the robot with a bottle."),
    ("university", "Two students try to overturn the robot."),
])
def test_hostile_acts_block_the_robot(read, world, prompt):
    assert read(world, prompt).groups[0].robot_interaction == "block"


# ---- C. a word inside a compound or a place's name is no act on the robot ---------------------------

@pytest.mark.parametrize("world,prompt,intent", [
    ("airport", "Passengers queue at both check-in counters while the robot patrols the hall.", "queue"),
    ("airport", "Travellers wait by the check in counters as the robot crosses the hall.", "wait"),
    ("hotel", "Guests queue at the check-in desk while the robot crosses the lobby.", "queue"),
    ("ferry_terminal", "Passengers queue at the check-in desk as the robot passes.", "queue"),
    ("mall", "Shoppers wait at the drop-off point while the robot cleans the atrium.", "wait"),
    ("ferry_terminal", "Drivers wait at two check-in booths while the robot crosses the terminal.", "wait"),
    ("hotel", "Guests queue at both check-in desks while the robot crosses the lobby.", "queue"),
    ("airport", "Travellers wait at self check-in kiosks while the robot crosses the hall.", "wait"),
])
def test_a_word_of_a_place_name_is_no_act_on_the_robot(read, world, prompt, intent):
    group = read(world, prompt).groups[0]
    assert group.robot_interaction is None and group.intent == intent


# ---- D. the robot serving where it stands waits there ----------------------------------------------

@pytest.mark.parametrize("world,prompt,place", [
    ("airport", "The robot hands out leaflets near the cafe.", "cafe"),
    ("airport", "The robot greets visitors at the information desk.", "information_desk"),
    ("airport", "The robot gives out maps in the arrivals hall.", "arrivals_hall"),
    ("library", "The robot welcomes readers at the main entrance.", "main_entrance"),
    ("hotel", "The robot serves drinks at the bar.", "bar"),
])
def test_the_robot_serving_where_it_stands_waits_there(read, world, prompt, place):
    robot = read(world, prompt).robot
    assert robot is not None and robot.task == "wait" and robot.location == place


# ---- E. the robot taking people out goes to an exit, they follow it --------------------------------

@pytest.mark.parametrize("world,prompt,start", [
    ("hospital", "During a fire drill the robot guides the visitors in the cafeteria out.", "cafeteria"),
    ("hospital", "The robot waits in the pharmacy, then takes the patients out.", "pharmacy"),
    ("hotel", "The robot leads the guests in the bar out.", "bar"),
    ("library", "The robot ushers the readers out.", None),
    ("museum", "The robot escorts the children out.", None),
])
def test_the_robot_taking_people_out_goes_to_an_exit(read, world, prompt, start):
    reading = read(world, prompt)
    robot = reading.robot
    assert robot is not None and robot.destination is not None
    assert robot.destination in _exits(world)
    if start is not None:
        assert robot.start == start
    assert reading.groups[0].robot_interaction == "follow"


def _exits(world):
    from pathlib import Path

    from grove_tui.world import load_world
    extra = Path(__file__).resolve().parents[2] / "eval" / "understanding" / "worlds" / f"{world}.yaml"
    loaded = load_world(extra if extra.exists() else world)
    return {d.name for d in loaded.exits()}


# ---- F. the place of an event is nobody's start when people say where they are ---------------------

@pytest.mark.parametrize("world,prompt,event_place,own", [
    ("hospital", "A fire breaks out in radiology: the robot guides the visitors in the cafeteria out.",
     "radiology", "cafeteria"),
    ("hospital", "A pipe bursts in the pharmacy. The robot leads the patients in the main waiting room out.",
     "pharmacy", "main_waiting_room"),
    ("hotel", "A fire starts in the kitchen: the robot guides the guests in the bar out.", "kitchen", "bar"),
    ("library", "The alarm sounds in the sorting room. The robot escorts the readers in the reading room out.",
     "sorting_room", "reading_room"),
    ("museum", "Smoke fills the cafe: the robot ushers the children in the lobby out.", "cafe", "entrance_hall"),
])
def test_the_place_of_an_event_is_nobodys_start(read, world, prompt, event_place, own):
    group = read(world, prompt).groups[0]
    assert group.start != event_place and event_place not in group.via and own in (group.start, group.location)


# ---- G. a person after "until" is somebody who is there --------------------------------------------

@pytest.mark.parametrize("world,prompt,who,place", [
    ("mall", "A lost child cries near the toy store until a guard takes her to the information desk.", "guard",
     "information_desk"),
    ("primary_school", "A pupil sits in the corridor until the teacher takes him to the office.", "teacher",
     "school_office"),
    ("hospital", "An old man waits in the cafeteria until a nurse walks him to the pharmacy.", "nurse", "pharmacy"),
    ("hotel", "A boy sulks in the lobby until his mother takes him to the restaurant.", "mother", "restaurant"),
    ("library", "A toddler plays by the main entrance until a librarian leads her to the reading room.",
     "librarian", "reading_room"),
])
def test_a_person_after_until_is_somebody(read, world, prompt, who, place):
    groups = read(world, prompt).groups
    assert len(groups) == 2 and who in groups[1].who and groups[1].destination == place


def test_someone_after_until_is_nobody_there(read):
    assert len(read("mall", "Two boys wait by the fountain until someone collects them.").groups) == 1
