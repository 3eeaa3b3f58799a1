"""A two-room world (a hall with a desk, a shop behind a door) for the map tests."""

TWO_ROOMS = """
name: two_rooms
description: A hall and a shop joined by a door.
zones:
  - name: hall
    type: lobby
    description: Entrance hall
    boundary: [[0, 0], [20, 0], [20, 10], [0, 10]]
    doors:
      - {name: main_entrance, position: [10, 0], width: 1.6, leads_to: outside, exit: true}
      - {name: shop_door, position: [20, 5], width: 1.2, leads_to: shop}
    entities:
      - name: desk
        type: counter
        footprint: [[4, 6], [8, 6], [8, 7], [4, 7]]
        interaction_point: [6, 5.4]
  - name: shop
    type: shop
    description: Shop
    boundary: [[20, 0], [30, 0], [30, 10], [20, 10]]
"""
