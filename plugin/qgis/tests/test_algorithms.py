"""Headless runs of the roofsweep algorithms through processing.run."""

import json
import os
import subprocess
import time

import processing
import pytest
from qgis.core import (QgsCoordinateReferenceSystem, QgsCoordinateTransform, QgsProcessingException, QgsProject,
                       QgsVectorLayer, QgsWkbTypes)

from conftest import RecordingFeedback, has_command, shared_or_skip

# The smallest block the simulator makes quickly (about 2 s): 2 nadir views
# of 3 buildings on 512x512 pixel images; the GSD is fixed so that the
# buildings fit in the footprint whatever the preset defaults become.
TINY = {"PRESET": 0, "SEED": 3, "SIZE": 512, "GSD": 0.15, "STRIPS": 1, "VIEWS": 2, "BUILDINGS": 3}
CITYMODEL_LAYERS = ("buildings", "roof_surfaces", "wall_surfaces", "ground_surfaces")


@pytest.fixture(scope="module")
def tiny_block(tmp_path_factory, roofsweep_exe):
    out = str(tmp_path_factory.mktemp("sim") / "block")
    fb = RecordingFeedback()
    res = processing.run("roofsweep:simulate", dict(TINY, OUTPUT=out), feedback=fb)
    return res, fb


def test_simulate_writes_block_and_reports_progress(tiny_block):
    res, fb = tiny_block
    assert os.path.isfile(res["BLOCK"])
    assert os.path.isfile(res["GROUNDTRUTH"])
    assert res["VIEW_COUNT"] == 2
    with open(os.path.join(res["OUTPUT"], "simulation.json")) as f:
        assert res["BUILDING_COUNT"] == json.load(f)["buildings"] > 0
    with open(res["BLOCK"]) as f:
        assert len(json.load(f)["images"]) == 2
    # GDAL dots became progress: it rose through the run and ended at 100.
    assert fb.progress_values and fb.progress_values[-1] == 100
    assert len(set(fb.progress_values)) >= 10
    assert fb.progress_values == sorted(fb.progress_values)
    assert any(line.startswith("Wrote ") for line in fb.console), fb.console
    assert not fb.errors


def test_simulate_on_a_slope_writes_a_dtm(tmp_path):
    out = str(tmp_path / "slope")
    res = processing.run("roofsweep:simulate", dict(TINY, TERRAIN_SLOPE=10, TERRAIN_ASPECT=60, OUTPUT=out),
                         feedback=RecordingFeedback())
    with open(res["BLOCK"]) as f:
        assert json.load(f)["ground"] == {"dtm": "dtm.tif"}
    assert os.path.isfile(os.path.join(out, "dtm.tif"))
    with open(os.path.join(out, "simulation.json")) as f:
        assert json.load(f)["terrain_slope_percent"] == 10


def test_simulate_over_hills_writes_a_dtm(tmp_path):
    out = str(tmp_path / "hills")
    res = processing.run("roofsweep:simulate", dict(TINY, TERRAIN_RELIEF=8, OUTPUT=out), feedback=RecordingFeedback())
    with open(res["BLOCK"]) as f:
        assert json.load(f)["ground"] == {"dtm": "dtm.tif"}
    with open(os.path.join(out, "simulation.json")) as f:
        assert json.load(f)["terrain_relief_m"] == 8


def test_simulate_refuses_to_replace_a_foreign_folder(tmp_path):
    keep = tmp_path / "mine.txt"
    keep.write_text("precious")
    with pytest.raises(QgsProcessingException, match="not empty"):
        processing.run("roofsweep:simulate", dict(TINY, OUTPUT=str(tmp_path)), feedback=RecordingFeedback())
    assert keep.read_text() == "precious"


def _gpkg_layer_checks(path, layers):
    counts = {}
    for name in CITYMODEL_LAYERS:
        uri = "{}|layername={}".format(path, name)
        assert uri in layers
        lyr = QgsVectorLayer(uri, name, "ogr")
        assert lyr.isValid(), name
        assert QgsWkbTypes.hasZ(lyr.wkbType()), name
        assert QgsWkbTypes.geometryType(lyr.wkbType()) == QgsWkbTypes.PolygonGeometry, name
        counts[name] = lyr.featureCount()
        assert counts[name] > 0, name
        for feat in lyr.getFeatures():
            g = feat.geometry()
            assert not g.isEmpty() and g.constGet().is3D()
    return counts


def _horizontal_epsg(crs):
    """EPSG code of the horizontal part of a (possibly 3D) QGIS CRS, via OSR."""
    from osgeo import osr

    srs = osr.SpatialReference()
    assert srs.ImportFromWkt(crs.toWkt(QgsCoordinateReferenceSystem.WKT2_2019)) == 0
    if srs.GetAxesCount() == 3:
        srs.DemoteTo2D()
    matches = [m for m, confidence in (srs.FindMatches() or []) if confidence == 100]
    if not matches:
        return None, None
    return matches[0].GetAuthorityName(None), matches[0].GetAuthorityCode(None)


def test_convert_groundtruth_to_gpkg_loads_3d_polygon_layers(tiny_block, tmp_path):
    res, _ = tiny_block
    out = str(tmp_path / "gt.gpkg")
    fb = RecordingFeedback()
    conv = processing.run("roofsweep:convert", {"INPUT": res["GROUNDTRUTH"], "FORMAT": 0, "OUTPUT": out},
                          feedback=fb)
    assert conv["OUTPUT"] == out and os.path.isfile(out)
    counts = _gpkg_layer_checks(out, conv["LAYERS"])
    n = res["BUILDING_COUNT"]
    assert counts["buildings"] == n
    assert counts["ground_surfaces"] == n
    assert counts["roof_surfaces"] >= n and counts["wall_surfaces"] >= 4 * n
    for name in CITYMODEL_LAYERS:
        crs = QgsVectorLayer("{}|layername={}".format(out, name), name, "ogr").crs()
        assert crs.isValid()
        assert _horizontal_epsg(crs) == ("EPSG", "25832"), crs.toWkt()
        assert crs.mapUnits() == 0  # QgsUnitTypes.DistanceMeters
    assert fb.progress_values and fb.progress_values[-1] == 100


def test_convert_queues_gpkg_layers_for_loading(tiny_block, tmp_path):
    from qgis.core import QgsProcessingContext, QgsProject

    res, _ = tiny_block
    out = str(tmp_path / "loaded.gpkg")
    fb = RecordingFeedback()
    context = QgsProcessingContext()
    context.setProject(QgsProject.instance())
    context.setFeedback(fb)
    processing.run("roofsweep:convert", {"INPUT": res["GROUNDTRUTH"], "OUTPUT": out}, context=context, feedback=fb)
    queued = context.layersToLoadOnCompletion()
    names = sorted(details.name for details in queued.values())
    assert names == sorted("loaded " + n for n in CITYMODEL_LAYERS), names
    for layer_id in queued:
        lyr = context.temporaryLayerStore().mapLayer(layer_id)
        assert lyr is not None and lyr.isValid() and lyr.source().startswith(out)


@pytest.mark.xfail(reason="roofsweep writes EPSG:25832 promoted to 3D (ellipsoidal height) as a custom "
                          "GeoPackage SRS; QGIS 3.22 shows it as 'ETRS89 / UTM zone 32N' without an authid",
                   strict=False)
def test_convert_gpkg_crs_authid_is_epsg_25832(tiny_block, tmp_path):
    res, _ = tiny_block
    out = str(tmp_path / "gt.gpkg")
    processing.run("roofsweep:convert", {"INPUT": res["GROUNDTRUTH"], "OUTPUT": out},
                   feedback=RecordingFeedback())
    crs = QgsVectorLayer(out + "|layername=roof_surfaces", "r", "ogr").crs()
    assert crs.authid() == "EPSG:25832"


def test_convert_to_cityjson_and_back(tiny_block, tmp_path):
    res, _ = tiny_block
    cj = str(tmp_path / "gt.city.json")
    processing.run("roofsweep:convert", {"INPUT": res["GROUNDTRUTH"], "FORMAT": 3, "OUTPUT": cj},
                   feedback=RecordingFeedback())
    with open(cj) as f:
        doc = json.load(f)
    assert doc["type"] == "CityJSON"
    n = res["BUILDING_COUNT"]
    assert sum(1 for o in doc["CityObjects"].values() if o["type"] == "Building") == n
    back = str(tmp_path / "back.gpkg")
    conv = processing.run("roofsweep:convert", {"INPUT": cj, "OUTPUT": back}, feedback=RecordingFeedback())
    assert _gpkg_layer_checks(back, conv["LAYERS"])["buildings"] == n


def test_failing_run_raises_with_the_error_line(tmp_path):
    bad = tmp_path / "broken.gml"
    bad.write_text("<core:CityModel xmlns:core='http://www.opengis.net/citygml/2.0'><oops></core:CityModel>")
    out = tmp_path / "x.gpkg"
    fb = RecordingFeedback()
    with pytest.raises(QgsProcessingException) as e:
        processing.run("roofsweep:convert", {"INPUT": str(bad), "OUTPUT": str(out)}, feedback=fb)
    msg = str(e.value)
    assert "roofsweep convert failed: ERROR" in msg and "broken.gml" in msg, msg
    assert any(err.startswith("ERROR") for err in fb.errors), fb.errors
    assert not out.exists()


def test_missing_input_is_refused_before_running(tmp_path):
    with pytest.raises(QgsProcessingException):
        processing.run("roofsweep:convert", {"INPUT": str(tmp_path / "nope.gml"), "OUTPUT": str(tmp_path / "o.gpkg")},
                       feedback=RecordingFeedback())


def _roofsweep_children():
    """Process ids of roofsweep programs started by this test process."""
    me = str(os.getpid())
    out = subprocess.run(["ps", "-o", "pid=,ppid=,comm=", "--ppid", me], stdout=subprocess.PIPE,
                         universal_newlines=True).stdout
    return [line.split()[0] for line in out.splitlines() if "roofsweep" in line]


def test_cancel_terminates_the_program(tmp_path):
    # The realistic preset renders 2048 px images: tens of seconds, so the
    # cancel (at the first progress dot past 5 %) lands mid-run.
    out = tmp_path / "cancelled"
    fb = RecordingFeedback(cancel_at=5)
    with pytest.raises(QgsProcessingException, match="cancelled"):
        processing.run("roofsweep:simulate", {"PRESET": 1, "SEED": 1, "STRIPS": 1, "VIEWS": 3,
                                              "OUTPUT": str(out)}, feedback=fb)
    # Cancel to exception: SIGTERM, at most 5 s grace, then SIGKILL.
    reaction = time.monotonic() - fb.cancelled_at
    assert fb.isCanceled()
    assert fb.progress_values and max(fb.progress_values) < 100
    assert not out.exists(), "a cancelled simulation must not leave its output folder"
    assert _roofsweep_children() == []
    assert reaction < 8, reaction


def test_cancel_leaves_no_temporary_folder(tmp_path):
    out = tmp_path / "cancelled"
    with pytest.raises(QgsProcessingException, match="cancelled"):
        processing.run("roofsweep:simulate", {"PRESET": 1, "SEED": 1, "STRIPS": 1, "VIEWS": 3,
                                              "OUTPUT": str(out)}, feedback=RecordingFeedback(cancel_at=5))
    assert sorted(os.listdir(tmp_path)) == []


def test_import_and_info_on_ngi_block(shared_dir, tmp_path, roofsweep_exe):
    ngi = shared_or_skip(shared_dir, "data/multiview/orthority-ngi-aerial")
    with open(os.path.join(ngi, "ngi_xyz_opk.prj")) as f:
        prj = f.read().strip()
    crs = QgsCoordinateReferenceSystem.fromProj(prj) if prj.startswith("+") else \
        QgsCoordinateReferenceSystem.fromWkt(prj)
    assert crs.isValid(), prj
    block = str(tmp_path / "ngi.json")
    fb = RecordingFeedback()
    res = processing.run("roofsweep:import", {
        "FORMAT": 0, "SOURCE": os.path.join(ngi, "camera_pos_ori.txt"),
        "CAMERA": os.path.join(ngi, "ngi_int_param.yaml"), "CRS": crs,
        "DTM": os.path.join(ngi, "dem.tif"), "OUTPUT": block}, feedback=fb)
    assert res["OUTPUT"] == block and os.path.isfile(block)
    with open(block) as f:
        manifest = json.load(f)
    assert len(manifest["images"]) == 4

    desc = str(tmp_path / "info.json")
    info = processing.run("roofsweep:info", {"BLOCK": block, "OUTPUT": desc}, feedback=RecordingFeedback())
    assert info["IMAGES"] == 4
    # 120 mm lens, 0.144 mm pixels, ~4.5 km above a 150-780 m DEM: GSD ~5 m.
    assert 3 < info["MEAN_GSD"] < 8, info["MEAN_GSD"]
    with open(desc) as f:
        assert len(json.load(f)["images"]) == 4


def test_import_folder_format_vgg_merton1(shared_dir, tmp_path):
    merton = shared_or_skip(shared_dir, "data/multiview/oxford-vgg/merton1")
    block = str(tmp_path / "merton1.json")
    processing.run("roofsweep:import", {"FORMAT": 5, "SOURCE_FOLDER": merton, "OUTPUT": block},
                   feedback=RecordingFeedback())
    info = processing.run("roofsweep:info", {"BLOCK": block}, feedback=RecordingFeedback())
    assert info["IMAGES"] == 3
    assert info["MEAN_GSD"] > 0


def test_import_needs_exactly_one_source(tmp_path):
    with pytest.raises(QgsProcessingException, match="exactly one"):
        processing.run("roofsweep:import", {"FORMAT": 0, "OUTPUT": str(tmp_path / "b.json")},
                       feedback=RecordingFeedback())


def test_eval_groundtruth_against_itself(tiny_block, tmp_path, roofsweep_exe):
    if not has_command(roofsweep_exe, "eval"):
        pytest.skip("roofsweep eval is not available in this build ({})".format(roofsweep_exe))
    res, _ = tiny_block
    report = str(tmp_path / "eval.json")
    vertices = str(tmp_path / "vertices.gpkg")
    out = processing.run("roofsweep:eval", {"RESULT": res["GROUNDTRUTH"], "GROUNDTRUTH": res["GROUNDTRUTH"],
                                            "OUTPUT": report, "VERTICES": vertices}, feedback=RecordingFeedback())
    with open(out["OUTPUT"]) as f:
        doc = json.load(f)
    # The truth scored against itself is perfect.
    assert doc["buildings"]["n_reference"] == res["BUILDING_COUNT"]
    assert out["BUILDING_COMPLETENESS"] == 1.0 and out["BUILDING_CORRECTNESS"] == 1.0
    assert out["ROOF_COMPLETENESS"] == 1.0 and out["ROOF_CORRECTNESS"] == 1.0
    assert out["RMSZ_M"] == pytest.approx(0.0, abs=1e-6)
    # ... and every vertex of the vertices layer lies on its outline.
    assert out["VERTICES"] == vertices
    layer = QgsVectorLayer(vertices + "|layername=vertices", "v", "ogr")
    assert layer.isValid() and layer.featureCount() > 8
    assert {f["place"] for f in layer.getFeatures()} == {"on the outline"}
    assert _horizontal_epsg(layer.crs()) == ("EPSG", "25832"), layer.crs().toWkt()


def test_overlay_of_the_true_model_lies_on_the_image_edges(tiny_block, tmp_path, roofsweep_exe):
    if not has_command(roofsweep_exe, "overlay"):
        pytest.skip("roofsweep overlay is not available in this build ({})".format(roofsweep_exe))
    res, _ = tiny_block
    out = processing.run("roofsweep:overlay", {"BLOCK": res["BLOCK"], "MODEL": res["GROUNDTRUTH"],
                                               "OUTPUT": str(tmp_path / "ov"), "REPORT": str(tmp_path / "ov.json")},
                         feedback=RecordingFeedback())
    assert sorted(os.listdir(out["OUTPUT"])) == ["s01_i001.png", "s01_i002.png"]
    assert out["ROOF_EDGES_ON_IMAGE_EDGES"] >= 0.9
    with open(out["REPORT"]) as f:
        assert len(json.load(f)["buildings"]) == res["BUILDING_COUNT"]


def test_lines_and_match_on_tiny_block(tiny_block, tmp_path, roofsweep_exe):
    for command in ("lines", "match"):
        if not has_command(roofsweep_exe, command):
            pytest.skip("roofsweep {} is not available in this build ({})".format(command, roofsweep_exe))
    res, _ = tiny_block
    seg = str(tmp_path / "segments.gpkg")
    lines = processing.run("roofsweep:lines", {"BLOCK": res["BLOCK"], "OUTPUT": seg}, feedback=RecordingFeedback())
    assert lines["OUTPUT"] == seg
    from osgeo import ogr

    ds = ogr.Open(seg)
    names = sorted(ds.GetLayer(i).GetName() for i in range(ds.GetLayerCount()))
    assert names == ["lines_s01_i001", "lines_s01_i002"], names
    assert all(ds.GetLayerByName(n).GetFeatureCount() > 0 for n in names)
    ds = None

    l3 = str(tmp_path / "lines3d.gpkg")
    fb = RecordingFeedback()
    match = processing.run("roofsweep:match", {"BLOCK": res["BLOCK"], "OUTPUT": l3,
                                               "TRUTH": os.path.join(res["OUTPUT"], "groundtruth_edges.json")},
                           feedback=fb)
    assert match["LAYERS"] == [l3 + "|layername=lines3d"]
    lyr = QgsVectorLayer(match["LAYERS"][0], "l3", "ogr")
    assert lyr.isValid() and lyr.featureCount() > 0
    assert QgsWkbTypes.hasZ(lyr.wkbType())
    assert QgsWkbTypes.geometryType(lyr.wkbType()) == QgsWkbTypes.LineGeometry
    assert _horizontal_epsg(lyr.crs()) == ("EPSG", "25832")
    assert fb.progress_values and fb.progress_values[-1] == 100
    assert any("3D lines" in c for c in fb.console), fb.console
    # A tile (the western half of the lines, in the block's CRS): only what
    # the images see of it and 30 m around it is matched.
    box = lyr.extent()
    tile = "{},{},{},{} [EPSG:25832]".format(box.xMinimum(), box.center().x(), box.yMinimum(), box.yMaximum())
    l3_tile = str(tmp_path / "lines3d_tile.gpkg")
    fb = RecordingFeedback()
    tiled = processing.run("roofsweep:match", {"BLOCK": res["BLOCK"], "OUTPUT": l3_tile, "EXTENT": tile},
                           feedback=fb)
    assert any(c.startswith("tile: ") for c in fb.console), fb.console
    part = QgsVectorLayer(tiled["LAYERS"][0], "tile", "ogr")
    assert part.isValid() and part.featureCount() > 0
    assert part.extent().xMinimum() > box.xMinimum() - 60 and part.extent().xMaximum() < box.center().x() + 60
    assert all(o.endswith(":-1") for f in part.getFeatures() for o in f["observations"].split())
    # lines reads the same windows; its segments keep the whole images'
    # pixel coordinates, so they lie within the images and beyond the
    # windows' own sizes where a window does not start at the corner.
    seg_tile = str(tmp_path / "segments_tile.gpkg")
    fb = RecordingFeedback()
    processing.run("roofsweep:lines", {"BLOCK": res["BLOCK"], "OUTPUT": seg_tile, "EXTENT": tile}, feedback=fb)
    assert any(c.startswith("tile: ") for c in fb.console), fb.console
    ds = ogr.Open(seg_tile)
    layers = [ds.GetLayer(i) for i in range(ds.GetLayerCount())]
    assert layers and all(lyr.GetFeatureCount() > 0 for lyr in layers)
    assert all("read for one tile" in lyr.GetMetadataItem("DESCRIPTION") for lyr in layers)
    ds = None


def test_unavailable_subcommand_fails_clearly(tmp_path, tiny_block):
    """A program lacking a subcommand (its --help exits 1) is named, and nothing runs."""
    from processing.core.ProcessingConfig import ProcessingConfig

    from roofsweep_qgis import runner

    log = tmp_path / "calls.txt"
    old = tmp_path / "roofsweep"
    old.write_text("#!/bin/sh\necho \"$@\" >> {}\n"
                   "echo \"ERROR 5: Unknown command '$1'\" >&2\nexit 1\n".format(log))
    old.chmod(0o755)
    res, _ = tiny_block
    ProcessingConfig.setSettingValue(runner.EXE_SETTING, str(old))
    try:
        for alg, command, params in (
                ("roofsweep:run", "run", {"BLOCK": res["BLOCK"], "OUTPUT": str(tmp_path / "b.gpkg")}),
                ("roofsweep:lines", "lines", {"BLOCK": res["BLOCK"], "OUTPUT": str(tmp_path / "s.gpkg")}),
                ("roofsweep:convert", "convert", {"INPUT": res["GROUNDTRUTH"],
                                                  "OUTPUT": str(tmp_path / "c.gpkg")})):
            with pytest.raises(QgsProcessingException,
                               match="roofsweep {} is not available in this build".format(command)):
                processing.run(alg, params, feedback=RecordingFeedback())
    finally:
        ProcessingConfig.setSettingValue(runner.EXE_SETTING, "")
    calls = log.read_text().splitlines()
    assert calls and all(line.endswith("--help") for line in calls), calls


def test_reconstruct_lod2_buildings_headless(tiny_block, roofsweep_exe, tmp_path):
    if not has_command(roofsweep_exe, "run"):
        pytest.skip("roofsweep run is not available in this build ({}): the 'run' subcommand is missing, "
                    "so Reconstruct LoD2 buildings cannot be tested".format(roofsweep_exe))
    # The sweep compares a reference view with at least two others: the
    # 2-view tiny block cannot give a roof plane, four views of it can.
    sim = processing.run("roofsweep:simulate", dict(TINY, VIEWS=4, OUTPUT=str(tmp_path / "block4")),
                         feedback=RecordingFeedback())
    out = str(tmp_path / "buildings.gpkg")
    fb = RecordingFeedback()
    report = str(tmp_path / "run.json")
    planes = str(tmp_path / "planes.gpkg")
    rec = processing.run("roofsweep:run", {"BLOCK": sim["BLOCK"], "OUTPUT": out, "REPORT": report,
                                           "PLANES": planes}, feedback=fb)
    assert os.path.isfile(out)
    # The plane hypotheses: each built or with a reason, loaded with the rest.
    hyp = QgsVectorLayer(planes + "|layername=roof_planes", "p", "ogr")
    assert hyp.isValid() and hyp.featureCount() > 0
    assert all(f["status"] == "built" or f["reason"] for f in hyp.getFeatures())
    assert planes + "|layername=roof_planes" in rec["LAYERS"]
    stages = [s["stage"] for s in json.load(open(report))["stages"]]
    assert "half-plane sweep" in stages and "LoD2 buildings" in stages, stages
    names = [u.split("layername=")[1] for u in rec["LAYERS"]]
    assert "buildings" in names and "roof_surfaces" in names
    lyr = QgsVectorLayer(out + "|layername=buildings", "b", "ogr")
    assert lyr.isValid() and QgsWkbTypes.hasZ(lyr.wkbType()) and lyr.featureCount() > 0
    assert _horizontal_epsg(lyr.crs()) == ("EPSG", "25832"), lyr.crs().toWkt()
    roofs = QgsVectorLayer(out + "|layername=roof_surfaces", "r", "ogr")
    assert roofs.isValid() and QgsWkbTypes.hasZ(roofs.wkbType()) and roofs.featureCount() > 0
    # With the simulator's footprints every building is labelled by one.
    fps = os.path.join(os.path.dirname(sim["BLOCK"]), "footprints.gpkg")
    out_fp = str(tmp_path / "buildings_fp.gpkg")
    processing.run("roofsweep:run", {"BLOCK": sim["BLOCK"], "OUTPUT": out_fp, "FOOTPRINTS": fps,
                                     "FOOTPRINT_ID": "id"}, feedback=RecordingFeedback())
    ids = {f["id"] for f in QgsVectorLayer(fps + "|layername=footprints", "f", "ogr").getFeatures()}
    built = QgsVectorLayer(out_fp + "|layername=buildings", "b", "ogr")
    assert built.isValid() and built.featureCount() > 0
    assert {f["footprint_id"] for f in built.getFeatures()} <= ids
    # A tile around the whole block, given in another CRS (WGS 84): the same
    # buildings, ids prefixed with the tile's corner in the block's CRS.
    box = lyr.extent()
    box.grow(50)
    to_wgs84 = QgsCoordinateTransform(lyr.crs(), QgsCoordinateReferenceSystem("EPSG:4326"), QgsProject.instance())
    geo = to_wgs84.transformBoundingBox(box)
    out_tile = str(tmp_path / "tile.gpkg")
    processing.run("roofsweep:run", {"BLOCK": sim["BLOCK"], "OUTPUT": out_tile, "EXTENT": "{},{},{},{} [EPSG:4326]".format(
        geo.xMinimum(), geo.xMaximum(), geo.yMinimum(), geo.yMaximum())}, feedback=RecordingFeedback())
    tiled = QgsVectorLayer(out_tile + "|layername=buildings", "t", "ogr")
    assert tiled.isValid() and tiled.featureCount() == lyr.featureCount()
    assert all(f["id"].startswith("t") and "_rs_b" in f["id"] for f in tiled.getFeatures())
