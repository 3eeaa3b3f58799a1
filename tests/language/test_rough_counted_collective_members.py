"""A rough count before a collective's members ("twelve or so club members", "a dozen or so choir
members") is the members' count: the collective is not joined to "so" as a name."""

from __future__ import annotations


def test_or_so_before_club_members(read):
    g = read("marina", "Twenty or so club members stroll from the car park to the bar.").groups
    assert len(g) == 1
    assert (g[0].count.kind, g[0].count.value) == ("approximate", 20)


def test_a_dozen_or_so_choir_members(read):
    g = read("hospital", "A dozen or so choir members walk from the reception to the cafeteria.").groups
    assert len(g) == 1
    assert g[0].count.kind == "approximate" and 9 <= g[0].count.value <= 15
    assert g[0].destination == "cafeteria"


def test_a_dozen_or_so_club_members_at_the_marina(read):
    g = read("marina", "A dozen or so club members saunter down from the bar to where the dinghies are launched.").groups
    assert len(g) == 1
    assert (g[0].count.kind, g[0].start, g[0].destination) == ("approximate", "club_bar", "slipway")
    assert 9 <= g[0].count.value <= 15
