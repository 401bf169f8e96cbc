"""Where the tests find the real AMR outputs they read (never part of the project)."""

import os
from pathlib import Path

import pytest


def real_data(relative):
    """The path of a real data set under $AMRSTREAM_SHARED_DATA (CTest sets it), else under
    ../shared/data/real beside the checkout; skips the test, saying so, when it is absent."""
    root = os.environ.get("AMRSTREAM_SHARED_DATA")
    root = Path(root) if root else Path(__file__).resolve().parents[3] / "shared" / "data" / "real"
    path = root / relative
    if not path.exists():
        pytest.skip(f"real data {path} is absent: set AMRSTREAM_SHARED_DATA to the folder that "
                    "holds the real data sets (../shared/data/real beside a full checkout)")
    return path
