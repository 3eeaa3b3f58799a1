"""GROVE-TUI: grounded pedestrian scenarios from a sentence, in the terminal, offline."""

import os

# Nothing ever leaves the machine: every hub client we depend on reads these at import time,
# so they are set before any of them can be imported.
for _key, _value in {
    "HF_HUB_OFFLINE": "1",
    "TRANSFORMERS_OFFLINE": "1",
    "HF_HUB_DISABLE_TELEMETRY": "1",
    "ANONYMIZED_TELEMETRY": "False",
    "TOKENIZERS_PARALLELISM": "false",
    # numba's OpenMP workers spin after each parallel step; on 2 cores that starves the Python
    # (behavior trees, UI) that runs next. Must be set before the OpenMP runtime starts.
    "OMP_WAIT_POLICY": "PASSIVE",
}.items():
    os.environ.setdefault(_key, _value)

__version__ = "0.1.0"
