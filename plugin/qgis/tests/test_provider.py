"""The provider loads, lists its algorithms and finds the program."""

import os
import subprocess
import sys

import pytest
from qgis.core import QgsApplication, QgsProcessingException

EXPECTED = {
    "roofsweep:import": "Import oriented images",
    "roofsweep:info": "Describe oriented block",
    "roofsweep:lines": "Extract line segments",
    "roofsweep:match": "Reconstruct 3D lines",
    "roofsweep:run": "Reconstruct LoD2 buildings",
    "roofsweep:eval": "Evaluate against ground truth",
    "roofsweep:overlay": "Check a model against the images",
    "roofsweep:simulate": "Simulate aerial block",
    "roofsweep:convert": "Convert LoD2 model",
}


def test_provider_is_registered_with_all_algorithms(provider):
    reg = QgsApplication.processingRegistry()
    assert reg.providerById("roofsweep") is provider
    ids = {a.id(): a.displayName() for a in provider.algorithms()}
    assert ids == EXPECTED
    for alg_id in EXPECTED:
        alg = reg.algorithmById(alg_id)
        assert alg is not None, alg_id
        assert alg.shortHelpString(), alg_id
        assert alg.group() == "roofsweep"


def test_plugin_entry_points_register_and_remove_provider():
    # In a fresh interpreter: unloading here would delete the session's provider.
    script = """
import sys
sys.path[:0] = [{parent!r}, '/usr/share/qgis/python/plugins']
from qgis.testing import start_app
app = start_app()
from qgis.core import QgsApplication
from processing.core.Processing import Processing
Processing.initialize()
import roofsweep_qgis
reg = QgsApplication.processingRegistry()
plugin = roofsweep_qgis.classFactory(None)
assert reg.providerById('roofsweep') is None
plugin.initGui()
assert reg.providerById('roofsweep') is plugin.provider
assert reg.algorithmById('roofsweep:convert') is not None
plugin.initProcessing()  # initGui after initProcessing must not register twice
assert [p.id() for p in reg.providers()].count('roofsweep') == 1
plugin.unload()
assert reg.providerById('roofsweep') is None
assert reg.algorithmById('roofsweep:convert') is None
print('PLUGIN-OK')
""".format(parent=os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    p = subprocess.run([sys.executable, "-c", script], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                       universal_newlines=True, timeout=120)
    assert p.returncode == 0 and "PLUGIN-OK" in p.stdout, p.stderr[-2000:]


def test_metadata_declares_processing_provider():
    import configparser

    here = os.path.dirname(os.path.abspath(__file__))
    cp = configparser.ConfigParser()
    cp.read(os.path.join(here, "..", "roofsweep_qgis", "metadata.txt"))
    assert cp["general"]["hasProcessingProvider"] == "yes"
    assert cp["general"]["qgisMinimumVersion"] == "3.22"


def test_executable_lookup_order(roofsweep_exe, monkeypatch, tmp_path):
    from processing.core.ProcessingConfig import ProcessingConfig

    from roofsweep_qgis import runner

    # Environment first when the provider setting is empty.
    ProcessingConfig.setSettingValue(runner.EXE_SETTING, "")
    monkeypatch.setenv("ROOFSWEEP_EXE", roofsweep_exe)
    assert runner.find_executable() == roofsweep_exe
    # The provider setting wins over the environment.
    fake = tmp_path / "roofsweep"
    fake.write_text("#!/bin/sh\nexit 0\n")
    fake.chmod(0o755)
    ProcessingConfig.setSettingValue(runner.EXE_SETTING, str(fake))
    try:
        assert runner.find_executable() == str(fake)
    finally:
        ProcessingConfig.setSettingValue(runner.EXE_SETTING, "")
    # A wrong environment value is named in the error when nothing else fits.
    monkeypatch.setenv("ROOFSWEEP_EXE", str(tmp_path / "missing"))
    monkeypatch.setenv("PATH", str(tmp_path / "empty"))
    monkeypatch.setattr(runner, "_build_tree_candidates", lambda: [])
    with pytest.raises(QgsProcessingException, match="missing"):
        runner.find_executable()


def test_progress_parser_follows_gdal_term_progress():
    from roofsweep_qgis.runner import ProgressParser

    p = ProgressParser()
    seen = []
    for ch in "0...10...20...30...40...50...60...70...80...90...100 - done.\nWrote out: 3 buildings\n":
        value, lines = p.feed(ch)
        if value is not None:
            seen.append(value)
        if lines:
            seen.append(lines)
    numeric = [v for v in seen if not isinstance(v, list)]
    assert numeric[0] == 0 and numeric[-1] == 100
    assert sorted(set(numeric)) == [2.5 * i for i in range(41)]
    assert numeric == sorted(numeric)
    assert ["Wrote out: 3 buildings"] in seen
