"""Fixtures for the roofsweep QGIS provider tests (QGIS started once, offscreen)."""

import os
import sys
import time

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
PLUGIN_PARENT = os.path.dirname(HERE)  # plugin/qgis, which holds roofsweep_qgis/
for p in (PLUGIN_PARENT, "/usr/share/qgis/python/plugins"):
    if p not in sys.path:
        sys.path.insert(0, p)

os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")
# QGIS computes statistics of the raster layers it opens (the NGI DEM) and
# would store them beside the file as .aux.xml, inside the shared data.
os.environ["GDAL_PAM_ENABLED"] = "NO"

from qgis.core import QgsProcessingFeedback  # noqa: E402
from qgis.testing import start_app  # noqa: E402

QGISAPP = start_app()

from processing.core.Processing import Processing  # noqa: E402

Processing.initialize()

import roofsweep_qgis  # noqa: E402

# Register through the plugin's own entry points, as QGIS does (iface is
# None under qgis_process).
_PLUGIN = roofsweep_qgis.classFactory(None)
_PLUGIN.initProcessing()
_PROVIDER = _PLUGIN.provider


class RecordingFeedback(QgsProcessingFeedback):
    """Keeps what an algorithm reported; optionally cancels at a progress value."""

    def __init__(self, cancel_at=None):
        super().__init__()
        self.progress_values = []
        self.errors = []
        self.infos = []
        self.console = []
        self.commands = []
        self.cancel_at = cancel_at
        self.cancelled_at = None  # time.monotonic() of the cancel request
        self.progressChanged.connect(self._on_progress)

    def _on_progress(self, value):
        self.progress_values.append(value)
        if self.cancel_at is not None and value >= self.cancel_at and not self.isCanceled():
            self.cancelled_at = time.monotonic()
            self.cancel()

    def reportError(self, error, fatalError=False):
        self.errors.append(error)

    def pushInfo(self, info):
        self.infos.append(info)

    def pushConsoleInfo(self, info):
        self.console.append(info)

    def pushCommandInfo(self, info):
        self.commands.append(info)


@pytest.fixture(scope="session")
def provider():
    return _PROVIDER


@pytest.fixture(scope="session")
def roofsweep_exe():
    from roofsweep_qgis import runner

    exe = os.environ.get("ROOFSWEEP_EXE")
    if not exe:
        exe = runner.find_executable()
        os.environ["ROOFSWEEP_EXE"] = exe
    assert os.access(exe, os.X_OK), "ROOFSWEEP_EXE is not executable: " + exe
    return exe


@pytest.fixture(scope="session")
def shared_dir():
    """Shared data folder: ROOFSWEEP_SHARED_DIR, else ../shared beside the checkout."""
    d = (os.environ.get("ROOFSWEEP_SHARED_DIR") or os.environ.get("ROOFSWEEP_SHARED_DIR_DEFAULT") or
         os.path.normpath(os.path.join(HERE, "..", "..", "..", "..", "shared")))
    return d


def shared_or_skip(shared_dir, rel):
    path = os.path.join(shared_dir, rel)
    if os.path.exists(path):
        return path
    if os.environ.get("ROOFSWEEP_REQUIRE_SHARED") == "1":
        pytest.fail("shared data missing (ROOFSWEEP_REQUIRE_SHARED=1): " + path)
    pytest.skip("shared data not found: " + path)


def has_command(exe, command):
    from roofsweep_qgis import runner

    return runner.command_help(exe, command)[0]


@pytest.fixture
def feedback():
    return RecordingFeedback()
