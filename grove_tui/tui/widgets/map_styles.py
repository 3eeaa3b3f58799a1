"""Style indexes of map cells, shared by the rasteriser and the widget (no numpy, so importing is instant)."""

FLOOR, WALL, ZONE_LABEL, DOOR, ENTITY, SPAWN, GOAL, WAYPOINT, FIELD, HIGHLIGHT, ROBOT, ROBOT_PATH, SELECTED = range(13)
GROUP_BASE = 13
GROUP_COLOURS = 8
STYLE_COUNT = GROUP_BASE + GROUP_COLOURS
