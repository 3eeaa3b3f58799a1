"""Stated head counts are read deterministically and attached to the noun they count."""

from __future__ import annotations

import pytest

from grove_tui.language.quantities import extract_quantities, lemma, semantic_tokens


def counts(prompt: str) -> list[tuple[int, str]]:
    return [(q.count, q.noun) for q in extract_quantities(prompt)]


@pytest.mark.parametrize(
    "prompt, expected",
    [
        ("Ten patients queue at the pharmacy counter", [(10, "patient")]),
        ("a dozen nurses chat in the staff room", [(12, "nurse")]),
        ("20 people wait in the lobby", [(20, "person")]),
        ("A couple walks to the cafeteria", [(2, "couple")]),
        ("a couple of visitors sit down", [(2, "visitor")]),
        ("a family of four waits near reception", [(4, "family")]),
        ("a group of 5 friends chat", [(5, "group")]),
        ("few visitors wander around", [(3, "visitor")]),
        ("a few visitors wander around", [(3, "visitor")]),
        ("several doctors walk to the ward", [(4, "doctor")]),
        ("10,000 people crowd into the bathroom", [(10000, "person")]),
        ("twenty-five students and a nurse", [(25, "student"), (1, "nurse")]),
        ("two hundred and ten people", [(210, "person")]),
        ("two dozen employees leave", [(24, "employee")]),
        ("ten of the patients leave", [(10, "patient")]),
        ("A family of four waits near the reception while 3 nurses walk by", [(4, "family"), (3, "nurse")]),
        ("Ten tired old patients leave", [(10, "patient")]),
        ("two groups of three chat", [(6, "group")]),
    ],
)
def test_stated_counts(prompt, expected):
    assert counts(prompt) == expected


@pytest.mark.parametrize(
    "prompt",
    [
        "a group of nurses talk in the corridor",
        "the robot crosses the lobby in 3 minutes",  # a number that counts no person
        "room 12 is busy",
    ],
)
def test_no_stated_count(prompt):
    assert counts(prompt) == []


def test_vague_words_are_marked_inexact_and_spans_point_into_the_prompt():
    prompt = "Several visitors and 4 nurses"
    first, second = extract_quantities(prompt)
    assert not first.exact and second.exact
    assert prompt[first.start:first.end] == "Several visitors" == first.phrase
    assert prompt[second.start:second.end] == "4 nurses"
    assert second.label_tokens == {"nurse"}


@pytest.mark.parametrize(
    "word, expected",
    [("nurses", "nurse"), ("pharmacies", "pharmacy"), ("benches", "bench"), ("people", "person"),
     ("children", "child"), ("glass", "glass"), ("bus", "bus"), ("status", "status"), ("lobby", "lobby")],
)
def test_lemma(word, expected):
    assert lemma(word) == expected


def test_semantic_tokens_drop_stopwords_and_numbers_but_keep_place_words():
    tokens = semantic_tokens("Ten patients queue at the pharmacies' counter; children wander in the waiting rooms")
    assert tokens == ["patient", "queue", "pharmacy", "counter", "child", "wander", "waiting", "room"]


def test_a_collective_without_a_size_means_a_plausible_group_not_one_person():
    from grove_tui.language.quantities import extract_quantities

    (family,) = extract_quantities("a family walks to the exit")
    assert family.count == 4 and not family.exact
    (families,) = extract_quantities("two families wait at reception")
    assert families.count == 8
    (sized,) = extract_quantities("a family of three walks in")
    assert sized.count == 3 and sized.exact


def test_a_bare_number_after_a_counted_phrase_borrows_its_noun():
    from grove_tui.language.quantities import extract_quantities

    counts = extract_quantities("twenty people in the cafeteria and ten in the pharmacy evacuate")
    assert [(q.count, q.noun) for q in counts] == [(20, "person"), (10, "person")]
    assert [q.count for q in extract_quantities("five nurses at 3 in the afternoon")] == [5]
    assert [q.count for q in extract_quantities("wait 10 minutes in the lobby")] == []


def test_a_bare_plural_subject_is_an_implied_group():
    from grove_tui.language.quantities import extract_quantities

    (implied,) = extract_quantities("patients queue at the pharmacy")
    assert implied.implied and not implied.exact and implied.noun == "patient"
    nurses, visitors = extract_quantities("four nurses chat in the staff room while visitors walk to ward a")
    assert (nurses.count, nurses.implied) == (4, False) and (visitors.noun, visitors.implied) == ("visitor", True)
    assert extract_quantities("the nurse helps patients in ward a") == []  # not who the clause is about
