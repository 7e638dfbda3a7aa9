# SPDX-License-Identifier: GPL-3.0-or-later
"""Shared fixtures of the Python tests."""
import json
import os

import pytest

FANDISK_JSON = os.path.join(os.path.dirname(__file__), "..", "..", "test", "Feature_segmentation", "data",
                            "fandisk.json")


@pytest.fixture(scope="session")
def fandisk_reference():
    """fandisk's figures at the defaults (test/Feature_segmentation/data/fandisk.json), the
    file the tests of every language read them from."""
    with open(FANDISK_JSON) as f:
        return json.load(f)
