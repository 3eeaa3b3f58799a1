"""Follow-up sentences read against a scenario's groups (language/followup.py and the followup_*.py
modules it runs; edited_reading in language/edits.py): what kind of edit, which group, which fields,
what count. Real spaCy, shipped worlds, no model."""

from __future__ import annotations

import pytest

from grove_tui.language.edits import EditReading, edited_reading
from grove_tui.language.followup import read_followup
from grove_tui.language.reading import read_prompt
from grove_tui.paths import worlds_dir
from grove_tui.world.loader import load_world

SCENES = {
    "hospital": "ten patients queue at the pharmacy while a family walks to the exit and a cleaner wanders "
                "in the main corridor",
    "office": "four colleagues chat in the kitchen while two managers walk to the boardroom",
    "airport": "twenty travellers queue at check-in while a family of four walks to the gates",
}


@pytest.fixture(scope="module")
def scenes():
    out = {}
    for name, prompt in SCENES.items():
        world = load_world(worlds_dir() / f"{name}.yaml")
        out[name] = (world, list(read_prompt(prompt, world, seed=0).groups))
    return out


def follow(scenes, world: str, sentence: str, **options) -> EditReading:
    w, groups = scenes[world]
    return read_followup(sentence, w, groups, **options)


def one(edit: EditReading):
    assert len(edit.edits) == 1, edit
    return edit.edits[0]


@pytest.mark.parametrize("sentence, label, count, intent, place", [
    ("add a cleaner mopping the corridor", "cleaner", 1, "wander", "main_corridor"),
    ("also two guards stand at the main entrance", "guard", 2, "wait", "main_entrance"),
    ("plus three visitors who walk to the cafeteria", "visitor", 3, "walk", "cafeteria"),
    ("two nurses chat in the lobby", "nurse", 2, "converse", "entrance_lobby"),
])
def test_additions_are_new_groups_read_by_the_reader(scenes, sentence, label, count, intent, place):
    edit = one(follow(scenes, "hospital", sentence))
    assert edit.kind == "add"
    g = edit.group
    assert (g.label, g.count.value, g.intent) == (label, count, intent)
    assert place in (g.location, g.destination, g.start)


def test_more_of_a_group_does_what_that_group_does(scenes):
    edit = one(follow(scenes, "hospital", "plus two more patients"))
    assert edit.kind == "add" and edit.target.targets == (0,)
    assert (edit.group.count.value, edit.group.intent, edit.group.location) == (2, "queue", "pharmacy")


@pytest.mark.parametrize("sentence, target, factor", [
    ("make the queue twice as long", 0, 2.0),
    ("double the family", 1, 2.0),
    ("halve the number of patients", 0, 0.5),
    ("the queue should be three times as long", 0, 3.0),
    ("twice as many patients", 0, 2.0),
])
def test_count_factors_name_their_group(scenes, sentence, target, factor):
    edit = one(follow(scenes, "hospital", sentence))
    assert (edit.kind, edit.target.targets, edit.count.kind, edit.count.value) == ("change", (target,), "factor", factor)


@pytest.mark.parametrize("sentence, kind, value", [
    ("make it 20 patients", "set", 20),
    ("only six patients", "set", 6),
    ("make the queue 15", "set", 15),
    ("two fewer patients", "delta", -2),
    ("remove two of the patients", "delta", -2),
])
def test_new_counts(scenes, sentence, kind, value):
    edit = one(follow(scenes, "hospital", sentence))
    assert (edit.kind, edit.target.targets, edit.count.kind, edit.count.value) == ("change", (0,), kind, value)


def test_a_change_takes_only_the_fields_it_states(scenes):
    w, groups = scenes["hospital"]
    edit = one(follow(scenes, "hospital", "the family walks slowly"))
    assert (edit.kind, edit.target.targets, edit.fields) == ("change", (1,), ("pace",))
    after = edited_reading(groups[1], edit)
    assert (after.pace, after.intent, after.destination, after.count) == ("slow", "walk", groups[1].destination,
                                                                           groups[1].count)


def test_instead_replaces_what_the_group_did(scenes):
    w, groups = scenes["hospital"]
    edit = one(follow(scenes, "hospital", "the patients walk to the cafeteria instead"))
    after = edited_reading(groups[0], edit)
    assert (after.intent, after.destination, after.location, after.count.value) == ("walk", "cafeteria", None, 10)


def test_a_robot_reaction_is_a_change(scenes):
    w, groups = scenes["hospital"]
    edit = one(follow(scenes, "hospital", "no, the cleaner should block the robot"))
    after = edited_reading(groups[2], edit)
    assert (after.robot_interaction, after.robot_reaction, after.location) == ("block", "Threatening", "main_corridor")


def test_a_group_named_by_its_place(scenes):
    edit = one(follow(scenes, "hospital", "the people at the pharmacy walk to the exit"))
    assert edit.target.targets == (0,) and "destination" in edit.fields


def test_everyone_is_every_group(scenes):
    edit = one(follow(scenes, "hospital", "everyone walks slowly"))
    assert edit.target.targets == (0, 1, 2) and edit.fields == ("pace",)


@pytest.mark.parametrize("sentence", ["remove the cleaner", "get rid of the cleaner", "without the cleaner",
                                      "the cleaner should not be there", "no cleaner"])
def test_removals(scenes, sentence):
    edit = one(follow(scenes, "hospital", sentence))
    assert (edit.kind, edit.target.targets) == ("remove", (2,))


def test_replace_removes_and_adds_a_group_doing_the_same(scenes):
    edits = follow(scenes, "hospital", "replace the cleaner with a guard").edits
    assert [e.kind for e in edits] == ["remove", "add"]
    assert (edits[1].group.label, edits[1].group.intent, edits[1].group.location) == ("guard", "wander", "main_corridor")


def test_two_edits_in_one_sentence(scenes):
    edits = follow(scenes, "hospital", "remove the cleaner and add two guards at the entrance").edits
    assert [(e.kind, e.group.label if e.group else e.target.targets) for e in edits] == [("remove", (2,)),
                                                                                        ("add", "guard")]


@pytest.mark.parametrize("sentence, kind, task, place", [
    ("no robot", "remove", None, None),
    ("remove the robot", "remove", None, None),
    ("the robot waits at reception", "set", "wait", "reception_desk"),
    ("now the robot crosses the lobby to the lifts", "set", "cross", "elevator_hall"),
    ("send the robot to the pharmacy", "set", "cross", "pharmacy"),
    ("add a robot", "add", None, None),
])
def test_the_robot(scenes, sentence, kind, task, place):
    edit = follow(scenes, "hospital", sentence)
    assert not edit.edits and edit.robot is not None and edit.robot.kind == kind
    if task is None:
        assert edit.robot.robot is None
    else:
        r = edit.robot.robot
        assert r.task == task and place in (r.location, r.destination)


def test_a_phrase_that_names_two_groups_is_ambiguous_until_chosen(scenes):
    world, groups = scenes["hospital"]
    more = groups + list(read_prompt("two nurses walk to the cafeteria and a nurse waits at reception", world).groups)
    edit = read_followup("the nurse walks slowly", world, more)
    (index, ref), = edit.ambiguities()
    assert ref.candidates == (3, 4)
    chosen = edit.choose(index, 4)
    assert not chosen.ambiguities() and chosen.edits[0].target.targets == (4,)
    assert EditReading.from_dict(chosen.to_dict()) == chosen


def test_a_pronoun_names_the_group_the_last_edit_touched(scenes):
    edit = one(follow(scenes, "hospital", "they walk slowly", last=(1,)))
    assert edit.target.targets == (1,)


def test_words_that_change_nothing_are_said(scenes):
    edit = follow(scenes, "hospital", "the lights are off")
    assert edit.empty and edit.notes


@pytest.mark.parametrize("world, sentence, target, field", [
    ("office", "the managers wait in the kitchen instead", 1, "location"),
    ("office", "the colleagues walk to the exit", 0, "destination"),
    ("airport", "the family walks quickly", 1, "pace"),
    ("airport", "make the queue twice as long", 0, "count"),
])
def test_other_worlds(scenes, world, sentence, target, field):
    edit = one(follow(scenes, world, sentence))
    assert edit.kind == "change" and edit.target.targets == (target,) and field in edit.fields


def test_a_pronoun_after_an_addition_names_the_new_group(scenes):
    add, change = follow(scenes, "hospital", "add a cleaner in the lobby and make it walk slowly").edits
    assert add.kind == "add" and change.kind == "change" and change.target.targets == (3,)  # after the three there
