"""The headless core: world, grid, planner, SFM, behavior trees, retrieval, pipeline, exports.

Never imports textual (enforced by tests/test_architecture.py).
"""
