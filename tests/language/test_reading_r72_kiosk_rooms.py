"""Round 72: a room that is itself a kiosk ("queue at the chip kiosk to buy fish and chips") is where
people served there queue, not a counter inside it (place_served)."""

from __future__ import annotations

from grove_tui.language.reading import read_prompt
from grove_tui.world import load_world


def test_a_kiosk_room_queued_at_to_buy_is_the_kiosk():
    g = read_prompt("Six day-trippers queue at the chip kiosk to buy fish and chips.",
                    load_world("eval/understanding/worlds/seaside_pier.yaml")).groups[0]
    assert (g.intent, g.location) == ("queue", "chip_kiosk")
