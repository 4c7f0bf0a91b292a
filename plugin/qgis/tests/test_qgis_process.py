"""The plugin as QGIS loads it: qgis_process.bin with a throwaway profile."""

import json
import os
import subprocess
import sys

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
PLUGIN_DIR = os.path.normpath(os.path.join(HERE, "..", "roofsweep_qgis"))
# The Debian wrapper /usr/bin/qgis_process passes --noversioncheck, which
# 3.22 rejects (qgis/QGIS#57683): call the binary.
QGIS_PROCESS = os.environ.get("ROOFSWEEP_QGIS_PROCESS", "/usr/bin/qgis_process.bin")


@pytest.fixture(scope="module")
def qgis_env(tmp_path_factory, roofsweep_exe):
    root = tmp_path_factory.mktemp("qgis_process")
    plugins = root / "plugins"
    plugins.mkdir()
    # Install what `make qgis-plugin` ships, not the source folder.
    import zipfile

    sys.path.insert(0, os.path.dirname(PLUGIN_DIR))
    from make_zip import make_zip

    zip_path = str(root / "roofsweep_qgis.zip")
    make_zip(zip_path)
    with zipfile.ZipFile(zip_path) as z:
        assert "roofsweep_qgis/metadata.txt" in z.namelist()
        assert not [n for n in z.namelist() if "__pycache__" in n or n.startswith("tests/")]
        z.extractall(str(plugins))
    cfg = root / "config"
    ini = cfg / "profiles" / "default" / "QGIS"
    ini.mkdir(parents=True)
    # Found through QGIS_PLUGINPATH is not enough: the profile must enable it.
    (ini / "QGIS3.ini").write_text("[PythonPlugins]\nroofsweep_qgis=true\n")
    runtime = root / "runtime"
    runtime.mkdir(mode=0o700)
    env = dict(os.environ, QT_QPA_PLATFORM="offscreen", XDG_RUNTIME_DIR=str(runtime),
               QGIS_CUSTOM_CONFIG_PATH=str(cfg), QGIS_PLUGINPATH=str(plugins), ROOFSWEEP_EXE=roofsweep_exe)
    # The plugin must not see the source tree's copy through PYTHONPATH.
    env["PYTHONPATH"] = ":".join(p for p in env.get("PYTHONPATH", "").split(":")
                                 if p and os.path.realpath(p) != os.path.realpath(os.path.dirname(PLUGIN_DIR)))
    return env


def qgis_process(env, *args, timeout=300):
    return subprocess.run([QGIS_PROCESS] + list(args), env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                          universal_newlines=True, timeout=timeout)


def test_qgis_process_lists_roofsweep_algorithms(qgis_env):
    p = qgis_process(qgis_env, "list")
    assert p.returncode == 0, p.stderr[-2000:]
    for alg in ("import", "info", "lines", "match", "run", "eval", "simulate", "convert"):
        assert "roofsweep:" + alg in p.stdout, (alg, p.stdout[-3000:], p.stderr[-2000:])
    assert "Convert LoD2 model" in p.stdout and "Reconstruct LoD2 buildings" in p.stdout


def test_qgis_process_help_shows_parameters(qgis_env):
    p = qgis_process(qgis_env, "help", "roofsweep:convert")
    assert p.returncode == 0, p.stderr[-2000:]
    for name in ("INPUT", "FORMAT", "OUTPUT"):
        assert name in p.stdout


def test_qgis_process_simulate_then_convert(qgis_env, tmp_path):
    block = tmp_path / "block"
    p = qgis_process(qgis_env, "--json", "run", "roofsweep:simulate", "--", "PRESET=0", "SEED=5", "SIZE=512",
                     "GSD=0.15", "STRIPS=1", "VIEWS=2", "BUILDINGS=2", "OBLIQUES=false", "OUTPUT=" + str(block))
    assert p.returncode == 0, p.stdout[-2000:] + p.stderr[-2000:]
    sim = json.loads(p.stdout)["results"]
    assert os.path.isfile(sim["GROUNDTRUTH"]) and sim["BUILDING_COUNT"] > 0

    out = tmp_path / "gt.gpkg"
    p = qgis_process(qgis_env, "run", "roofsweep:convert", "--INPUT=" + sim["GROUNDTRUTH"], "--FORMAT=0",
                     "--NO_CHECK=false", "--ALLOW_EMPTY=false", "--OUTPUT=" + str(out))
    assert p.returncode == 0, p.stdout[-2000:] + p.stderr[-2000:]
    assert "OUTPUT:\t" + str(out) in p.stdout or str(out) in p.stdout
    from osgeo import ogr

    ds = ogr.Open(str(out))
    layers = {ds.GetLayer(i).GetName(): ds.GetLayer(i).GetFeatureCount() for i in range(ds.GetLayerCount())}
    assert layers["buildings"] == sim["BUILDING_COUNT"] and layers["roof_surfaces"] > 0, layers


def test_qgis_process_reports_program_errors(qgis_env, tmp_path):
    bad = tmp_path / "bad.city.json"
    bad.write_text('{"type": "CityJSON", "version": "2.0"')
    p = qgis_process(qgis_env, "run", "roofsweep:convert", "--INPUT=" + str(bad), "--OUTPUT=" + str(tmp_path / "o.gpkg"))
    assert p.returncode == 1
    out = p.stdout + p.stderr
    assert "roofsweep convert failed: ERROR" in out and "bad.city.json" in out, out[-2000:]
