"""What a keyboard, a phone or a chat window adds to English (language/text.py): full-width letters,
emoji, lone surrogates, chat abbreviations and numbers with a fraction are read as the English they
stand for, never refused as "only symbols" nor turned into other numbers."""

from __future__ import annotations

import pytest

from grove_tui.language.reading import read_prompt
from grove_tui.language.text import normalise


@pytest.mark.parametrize("typed,read", [
    ("Ｆｏｕｒ ｎｕｒｓｅｓ ｗａｌｋ", "Four nurses walk"),
    ("👩‍⚕️ A nurse walks 🚶🏽 to the lift", "A nurse walks to the lift"),
    ("two\ud800 nurses", "two nurses"),
    ("3 ppl & 2 nurses w/ a porter", "3 people and 2 nurses with a porter"),
    ("Ppl wait 5 mins", "People wait 5 minutes"),
    ("the café", "the café"),
    ("🙂🙂", ""),
])
def test_normalised_text(typed, read):
    assert normalise(typed) == read


@pytest.mark.parametrize("prompt,value", [
    ("Ｆｉｖｅ ｐａｔｉｅｎｔｓ walk to the cafeteria.", 5),
    ("🧑‍🤝‍🧑 Six visitors walk to the cafeteria.", 6),
    ("7 ppl walk to the cafeteria", 7),
    ("a dozen peeps walk to the cafeteria", 12),
])
def test_counts_survive_what_phones_and_chats_add(hospital, prompt, value):
    reading = read_prompt(prompt, hospital)
    assert [g.count.value for g in reading.groups] == [value]
    assert reading.groups[0].destination == "cafeteria" and reading.unknown_places == ()
    assert reading.prompt == " ".join(prompt.split())  # the reading keeps what the user typed


@pytest.mark.parametrize("number,low,high,value", [("2.5", 2, 3, 3), ("3.2", 3, 4, 3), ("1.5", 1, 2, 2)])
def test_a_count_with_a_fraction_is_the_whole_numbers_around_it(hospital, number, low, high, value):
    g = read_prompt(f"{number} people walk to the cafeteria.", hospital).groups[0]
    assert (g.count.kind, g.count.low, g.count.high, g.count.value) == ("approximate", low, high, value)


def test_an_emoji_family_is_a_family(hospital):
    g = read_prompt("👨‍👩‍👧‍👦 A family walks to the pharmacy.", hospital).groups[0]
    assert g.count.kind == "implied" and 3 <= g.count.value <= 4 and g.destination == "pharmacy"
