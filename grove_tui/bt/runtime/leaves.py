"""BT.CPP's built-in leaves (AlwaysSuccess, AlwaysFailure, SetBlackboard)."""

from __future__ import annotations

from grove_tui.bt.runtime.tree_node import FAILURE, SUCCESS, LeafNode, SyncActionNode


class AlwaysSuccess(SyncActionNode):
    __slots__ = ()

    def tick(self) -> int:
        return SUCCESS


class AlwaysFailure(SyncActionNode):
    __slots__ = ()

    def tick(self) -> int:
        return FAILURE


class SetBlackboard(SyncActionNode):
    __slots__ = ()

    def tick(self) -> int:
        key = self.get_input("output_key")
        self.blackboard.set(str(key), self.get_input("value"))
        return SUCCESS


BTCPP_LEAVES: dict[str, type[LeafNode]] = {
    "AlwaysSuccess": AlwaysSuccess, "AlwaysFailure": AlwaysFailure, "SetBlackboard": SetBlackboard,
}
