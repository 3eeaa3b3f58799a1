"""A full stop after a capital initial or a title inside a name is no sentence end ("the T. rex", "St.
John's chapel", "J. K. Bloggs"): the name is read whole (name_stops.py); a lone letter before a capital
word keeps its stop ("gate B. Then ...")."""

from __future__ import annotations

from grove_tui.language.name_stops import names_unstopped


def test_the_initial_is_part_of_the_name(read):
    r = read("museum", "Ten pupils sketch the T. rex while two teachers chat in the cafe.")
    assert r.unknown_places == ()
    assert r.groups[0].location == "t_rex_skeleton"


def test_a_name_the_world_lacks_is_refused_whole(read):
    r = read("railway_museum", "Of the twenty pupils crowded round the T. rex, six walk to the cafe.")
    assert "t" not in r.unknown_places
    assert r.groups[-1].destination == "refreshment_room"


def test_a_title_is_no_sentence_end(read):
    (g,) = read("cathedral", "Two vergers wait in St. John's chapel.").groups
    assert g.location == "st_johns_chapel"


def test_the_stops_dropped_and_kept():
    assert names_unstopped("A guide called J. K. Bloggs waits by the T. rex.") == \
        "A guide called J K Bloggs waits by the T rex."
    assert names_unstopped("Five pupils gather at gate B. Then two teachers leave.") == \
        "Five pupils gather at gate B. Then two teachers leave."
    assert names_unstopped("Dr. Patel walks to St. Mary's ward.") == "Dr Patel walks to St Mary's ward."
