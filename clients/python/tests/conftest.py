import os
import sys

import pytest

sys.path.insert(0, os.path.dirname(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "src"))

from deployment import PioneerRig  # noqa: E402


@pytest.fixture(scope="session")
def rig(tmp_path_factory):
    """The simulated Pioneer and a daemon with config/pioneer.json, security on, for the whole session."""
    r = PioneerRig(str(tmp_path_factory.mktemp("pioneer")))
    try:
        r.start_simulator()
        r.start_daemon()
        r.await_ready()
        yield r
    finally:
        r.close()
