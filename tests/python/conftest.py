# The module under test is the one built: PYTHONPATH=build/<preset>/python
# (CTest sets it; see tests/CMakeLists.txt).
import pytest


@pytest.fixture(scope="session")
def fv():
    import foveate

    return foveate
