"""Round 13 of the reader's people, as decided again in round 44 (2026-11-30): a person and a companion named
by a possessive are one group per noun phrase, each of one person with the clause's fields, and a couple (kin,
or a partner named by a possessive) is one group of two who keep together (the writers' labels); compound
agent nouns keep their count; one person acting twice on the robot is one group with the later, further
reaction; "the only other person" is one more person, not everyone; an adjective standing for a person is one."""

import pytest

PAIRS = [
    ("hotel", "A mother and her toddler walk from the lobby to the restaurant.", "mother and toddler"),
    ("residential", "A plumber and his apprentice walk from the kitchen to the bathroom.", "plumber and apprentice"),
    ("primary_school", "The teacher and her assistant wait in the foyer.", "teacher and assistant"),
    ("library", "An old man and his granddaughter walk to the reading room.", "man and granddaughter"),
]

COUPLES = [
    ("residential", "Mum and Dad head off to their bedroom.", "mum and dad"),
    ("residential", "Grandma and grandpa doze on the sofa.", "grandma and grandpa"),
    ("hotel", "A husband and wife check in at reception.", "husband and wife"),
    ("hotel", "The bride and groom walk from the lobby to the bar.", "bride and groom"),
    ("library", "An old man and his wife walk to the reading room.", "man and wife"),
]


@pytest.mark.parametrize("world,prompt,label", PAIRS)
def test_a_pair_is_two_groups_of_one_with_the_same_fields(read, world, prompt, label):
    one, other = read(world, prompt).groups
    assert f"{one.label} and {other.label}" == label
    assert (one.count.value, other.count.value, one.together, other.together) == (1, 1, False, False)
    fields = ("intent", "start", "destination", "location", "robot_reaction")
    assert [getattr(one, f) for f in fields] == [getattr(other, f) for f in fields]


@pytest.mark.parametrize("world,prompt,label", COUPLES)
def test_a_couple_is_one_group_of_two_together(read, world, prompt, label):
    g, = read(world, prompt).groups
    assert (g.label, g.count.value, g.together) == (label, 2, True)


@pytest.mark.parametrize("world,prompt,counts", [
    ("hospital", "Two surgeons and an anaesthetist walk to reception.", [2, 1]),
    ("residential", "The au pair and the baby sit in the living room.", [1, 1]),
    ("mall", "Mum and two kids walk to the food court.", [1, 2]),
    ("hospital", "A porter wheels a patient to x-ray and her husband follows.", [1, 1, 1]),
    ("office", "A manager and two interns walk to the kitchen.", [1, 2]),
])
def test_other_coordinated_people_stay_one_group_per_noun(read, world, prompt, counts):
    groups = read(world, prompt).groups
    assert [g.count.value for g in groups] == counts
    assert not any(g.together for g in groups)


def test_a_pair_after_another_group_keeps_the_relations_after_it(read):
    groups = read("hotel", "A mother and her son walk to the bar; two porters wait in the lobby and one of them "
                           "walks to reception.").groups
    assert [g.count.value for g in groups][:3] == [1, 1, 2]
    assert groups[-1].relation == "subset_of:2"


@pytest.mark.parametrize("world,prompt,label,count", [
    ("supermarket", "Three shelf stackers walk from the stockroom to aisle 3.", "stacker", 3),
    ("supermarket", "While two trolley pushers wait at the entrance, four shelf fillers walk to aisle 3.", "filler", 4),
    ("station", "Four ticket checkers stand at the gateline.", "checker", 4),
    ("office", "Two window cleaners walk from the lobby to the kitchen.", "cleaner", 2),
    ("warehouse", "Five forklift drivers wait in dispatch.", "driver", 5),
])
def test_a_noun_and_verb_er_person_keeps_its_count(read, world, prompt, label, count):
    groups = read(world, prompt).groups
    g = groups[-1]
    assert (g.label, g.count.kind, g.count.value) == (label, "exact", count)


@pytest.mark.parametrize("world,prompt", [
    ("office", "Two leaf blowers hum in the kitchen."),
    ("hospital", "Two paper shredders whir in the office."),
])
def test_things_named_like_agents_are_nobody(read, world, prompt):
    assert all(g.label == "person" for g in read(world, prompt).groups)


@pytest.mark.parametrize("world,prompt,reaction", [
    ("mall", "A toddler waves at the robot and toddles after it.", "follow"),
    ("museum", "A child waves at the robot and then follows it.", "follow"),
    ("station", "A boy smiles at the robot and trots after it.", "follow"),
    ("airport", "A child stares at the robot and then runs away from it.", "avoid"),
    ("office", "Two interns walk up to the robot and stare at it.", "approach"),
])
def test_one_person_acting_twice_on_the_robot_is_one_group(read, world, prompt, reaction):
    groups = read(world, prompt).groups
    assert len(groups) == 1
    assert groups[0].robot_interaction == reaction


@pytest.mark.parametrize("world,prompt,counts", [
    ("office", "The only other person is a guard.", [1]),
    ("office", "Two developers code at their desks; the only other person is a guard at reception.", [2, 1]),
    ("museum", "The only other people in the gallery are three students.", [3]),
])
def test_the_only_other_person_is_no_exclusive_count(read, world, prompt, counts):
    groups = read(world, prompt).groups
    assert [(g.count.kind, g.count.value) for g in groups] == [("exact", c) for c in counts]


def test_the_only_people_still_say_nobody_else(read):
    groups = read("hospital", "The only people in the ward are two nurses.").groups
    assert [(g.count.kind, g.count.value) for g in groups] == [("exclusive", 2)]


@pytest.mark.parametrize("world,prompt,label,interaction", [
    ("station", "A drunk kicks the robot.", "drunk", "block"),
    ("airport", "A drunk shouts at the robot.", "drunk", "block"),
    ("mall", "A local yells at the robot.", "local", "block"),
    ("station", "A drunk staggers to the exit.", "drunk", None),
    ("hotel", "A regular waits at the bar.", "regular", None),
])
def test_an_adjective_standing_for_a_person_is_one_person(read, world, prompt, label, interaction):
    groups = read(world, prompt).groups
    assert len(groups) == 1
    g = groups[0]
    assert (g.label, g.count.kind, g.count.value, g.robot_interaction) == (label, "exact", 1, interaction)
    if interaction == "block":
        assert g.robot_reaction == "Threatening"


@pytest.mark.parametrize("world,prompt", [
    ("hospital", "The injured wait in the waiting room."),
    ("hotel", "The elderly rest in the lobby."),
])
def test_the_adjective_plural_is_some_people(read, world, prompt):
    g = read(world, prompt).groups[0]
    assert g.count.kind == "vague" and g.count.value > 1


def test_an_adjective_before_its_noun_stays_an_adjective(read):
    g = read("hotel", "A blind man walks to reception.").groups[0]
    assert (g.label, g.count.value) == ("man", 1)


@pytest.mark.parametrize("world,prompt,labels", [
    ("residential", "The kids and their nan bake in the kitchen.", ["kid", "nan"]),
    ("residential", "The kids and their mum bake in the kitchen.", ["kid", "mum"]),
    ("hotel", "Two porters and a bellboy chill in the lobby.", ["porter", "bellboy"]),
])
def test_people_joined_before_a_verb_no_list_names_share_its_place(read, world, prompt, labels):
    groups = read(world, prompt).groups
    assert [g.label for g in groups] == labels
    assert len({g.location for g in groups}) == 1 and groups[0].location is not None


@pytest.mark.parametrize("world,prompt", [
    ("ferry_terminal", "A couple with a baby wait in the departure lounge."),
    ("hotel", "A couple with a toddler sit in the bar."),
])
def test_a_couple_with_one_companion_keeps_its_two(read, world, prompt):
    groups = read(world, prompt).groups
    assert (groups[0].label, groups[0].count.value) == ("couple", 2)
    assert [g.count.value for g in groups[1:]] == [1]


@pytest.mark.parametrize("world,prompt,interaction", [
    ("library", "A toddler crawls towards the robot.", "approach"),
    ("mall", "Two kids wander over to the robot.", "approach"),
    ("courthouse", "A handful of reporters crowd the robot outside courtroom 2.", "approach"),
    ("mall", "A gang of teenagers surround the robot.", "approach"),
    ("museum", "An artist sketches the robot from the bench.", "look"),
    ("courthouse", "A court artist draws the robot outside courtroom 2.", "look"),
])
def test_reactions_by_verbs_the_lists_lacked(read, world, prompt, interaction):
    assert [g.robot_interaction for g in read(world, prompt).groups] == [interaction]


def test_depicting_something_else_is_no_reaction(read):
    g, = read("museum", "A student sketches the whale skeleton for forty-five minutes.").groups
    assert (g.robot_interaction, g.location) == (None, "whale_skeleton")


@pytest.mark.parametrize("world,prompt,labels", [
    ("airport", "The pilot and the co-pilot walk to the gate.", ["pilot", "co-pilot"]),
    ("office", "Three co-workers chat in the kitchen.", ["co-worker"]),
    ("residential", "Her ex-husband waits in the hallway.", ["ex-husband"]),
])
def test_a_hyphen_prefixed_person_is_one_person_noun(read, world, prompt, labels):
    groups = read(world, prompt).groups
    assert [g.label for g in groups] == labels


def test_a_pair_with_a_hyphen_prefixed_companion(read):
    pilot, co_pilot = read("airport", "A pilot and his co-pilot walk to the gate.").groups
    assert (pilot.label, co_pilot.label, co_pilot.count.value, co_pilot.destination) == ("pilot", "co-pilot", 1, "gate_a1")


def test_an_agent_of_a_real_verb_is_not_corrected_to_another_person(read):
    groups = read("warehouse", "A picker and a packer chat at the packing bench.").groups
    assert [g.label for g in groups] == ["picker", "packer"]


@pytest.mark.parametrize("world,prompt,kind,count,label", [
    ("hospital", "The only nurse on the ward walks to the pharmacy.", "exact", 1, "nurse"),
    ("museum", "The only other visitor walks to the cafe.", "exact", 1, "visitor"),
    ("hospital", "The only visitors in the cafeteria are two students.", "exclusive", 2, "student"),
    ("museum", "The only visitor in the gallery is a student sketching.", "exclusive", 1, "student"),
])
def test_the_only_person_noun(read, world, prompt, kind, count, label):
    g, = read(world, prompt).groups
    assert (g.count.kind, g.count.value, g.label) == (kind, count, label)


@pytest.mark.parametrize("world,prompt,label,destination", [
    ("ferry_terminal", "A lorry driver and his mate queue at check-in.", "driver and mate", None),
    ("hospital", "A paramedic and his partner wheel a stretcher to the ward.", "paramedic and partner", "ward_a"),
])
def test_a_companion_before_a_verb_the_parser_calls_a_noun(read, world, prompt, label, destination):
    one, other = read(world, prompt).groups
    assert f"{one.label} and {other.label}" == label
    assert [(g.count.value, g.destination, g.intent) for g in (one, other)] == [(1, destination, one.intent)] * 2



@pytest.mark.parametrize("world,prompt,interaction", [
    ("library", "Two students stop whispering when the robot passes.", None),
    ("warehouse", "A forklift driver stops to let the robot cross.", "avoid"),
    ("station", "A commuter stops for the robot.", "avoid"),
    ("hospital", "A porter waits to let the robot pass.", "avoid"),
    ("hospital", "A nurse waits for the robot at reception.", None),
    ("mall", "Two guards stop the robot at the entrance.", "block"),
])
def test_stopping_for_the_robot_is_making_way_and_stopping_an_activity_is_nothing(read, world, prompt, interaction):
    assert read(world, prompt).groups[0].robot_interaction == interaction


@pytest.mark.parametrize("prompt,count,who", [
    ("The jury walk to the jury room.", 12, "The jury"),
    ("Two ushers lead the jury from courtroom 1 to the jury room.", 12, "the jury"),
    ("A clerk waits in the jury room.", 1, "A clerk"),
])
def test_the_jury_is_twelve_people(read, prompt, count, who):
    g = read("courthouse", prompt).groups[-1]
    assert (g.who, g.count.value) == (who, count)
