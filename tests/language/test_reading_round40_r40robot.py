"""Robot and purpose classes of round 40, each with sentences of its own over at least two worlds (none
from the understanding sets): the robot's job given as a heading ("Robot job: take ...", "Task for the
robot - fetch ...", "The robot's task is to deliver ..."); a purpose said first, before the people
("Needing a coffee, two nurses walk ...")."""

from __future__ import annotations

import pytest


# ---- 1. the robot's job given as a heading ----------------------------------------------------------------

@pytest.mark.parametrize("world,prompt,task,start,destination", [
    ("hospital", "Robot task: fetch blankets from the pharmacy to the cafeteria while two nurses chat at reception.",
     "cross", "pharmacy", "cafeteria"),
    ("hospital", "Job for the robot - carry the post from reception to the pharmacy. Two porters wait by the lifts.",
     "cross", "reception_desk", "pharmacy"),
    ("office", "Two staff chat in the kitchen. The robot's task is to deliver the mail from reception to the kitchen.",
     "cross", "reception", "kitchen"),
    ("museum", "Robot's errand this morning: bring a wheelchair from the cloakroom to the café. Two visitors "
     "chat in the great hall.", "cross", "cloakroom", "cafe"),
    ("library", "Robot job: take the returned books from the issue desk to the reading room. A student naps "
     "in the reading room.", "cross", "issue_desk", "reading_room"),
    ("office", "Robot: wait by reception. Two staff chat in the kitchen.", "wait", None, None),
    ("office", "Robot task: patrol the corridor. Two staff chat in the kitchen.", "patrol", None, None),
])
def test_a_job_given_as_a_heading_is_the_robots_task(read, world, prompt, task, start, destination):
    r = read(world, prompt)
    assert r.robot is not None and r.robot.task == task
    assert (r.robot.start, r.robot.destination) == (start, destination)
    assert len(r.groups) == 1


# ---- guards: a heading over no verb, and "the robot" said plainly, keep their reading --------------------

@pytest.mark.parametrize("world,prompt,task", [
    ("museum", "Robot job: tea run to the café. Two visitors chat in the great hall.", None),
    ("hospital", "The robot crosses from reception to the pharmacy while two nurses chat.", "cross"),
    ("office", "Have the robot wait by reception. Two staff chat in the kitchen.", "wait"),
])
def test_headings_over_no_verb_and_plain_robots_keep_their_reading(read, world, prompt, task):
    r = read(world, prompt)
    assert (r.robot.task if r.robot is not None else None) == task


# ---- 2. a purpose said first, before the people --------------------------------------------------------

@pytest.mark.parametrize("world,prompt,wanted,destination", [
    ("hospital", "Needing a coffee, two nurses walk from reception to the cafeteria.", "coffee", "cafeteria"),
    ("hospital", "Wanting painkillers, a man heads to the pharmacy.", "painkiller", "pharmacy"),
    ("office", "Wanting a printer, a manager walks from reception to the kitchen. Two staff chat in the kitchen.",
     "printer", "kitchen"),
    ("museum", "Seeking a souvenir for her nan, a girl walks from the great hall to the gift shop.", "souvenir",
     "gift_shop"),
    ("library", "Wanting a quiet desk, a student walks from the issue desk to the reading room.", "quiet desk",
     "reading_room"),
])
def test_a_want_said_first_is_the_peoples_purpose(read, world, prompt, wanted, destination):
    group = read(world, prompt).groups[0]
    assert wanted in (group.purpose or "").lower()
    assert group.destination == destination


# ---- guards: wanting to go, and a want said after the people, keep their reading --------------------------

@pytest.mark.parametrize("world,prompt,purpose", [
    ("hospital", "Wanting to leave, two visitors walk to the main entrance.", "to leave"),
    ("museum", "Two students, wanting postcards, cross from the cloakroom to the gift shop.", "wanting postcards"),
])
def test_wanting_to_go_and_wants_said_later_keep_their_reading(read, world, prompt, purpose):
    (group,) = read(world, prompt).groups
    assert group.purpose == purpose


# ---- 3. the robot passing people said by the verb alone ---------------------------------------------------

@pytest.mark.parametrize("world,prompt,passes,via", [
    ("hospital", "Six visitors queue at reception while the robot passes them on its way to the pharmacy.",
     "Six visitors", "reception_desk"),
    ("mall", "A dozen shoppers wait by the fountain; the robot overtakes them on the way to the food court.",
     "A dozen shoppers", "fountain"),
    ("museum", "Ten kids queue at the café and the robot skirts the queue on its way to the great hall.",
     "Ten kids", "cafe"),
    ("office", "Two staff chat at reception as the robot passes them on its way to the kitchen.", "Two staff",
     "reception"),
])
def test_people_the_robot_passes_by_verb_are_passed(read, world, prompt, passes, via):
    r = read(world, prompt)
    assert r.robot is not None and r.robot.task == "cross"
    assert passes in r.robot.passes and via in r.robot.via


# ---- guards: passing a place, and passing by with a preposition, keep their reading -------------------------

@pytest.mark.parametrize("world,prompt,passes,via", [
    ("station", "The robot passes the gateline on its way to platform 2 while a guard waits by the ticket office.",
     (), ("gateline",)),
    ("mall", "A dozen shoppers queue at the cinema; the robot goes past the queue to the food court.",
     ("A dozen shoppers",), ("cinema_lobby",)),
])
def test_passing_a_place_or_passing_by_keeps_its_reading(read, world, prompt, passes, via):
    r = read(world, prompt)
    assert r.robot is not None and (r.robot.passes, r.robot.via) == (passes, via)
