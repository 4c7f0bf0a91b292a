"""Shared plumbing of the roofsweep Processing algorithms."""

import json
import os

from qgis.core import (QgsCoordinateReferenceSystem, QgsProcessingAlgorithm, QgsProcessingContext,
                       QgsProcessingException, QgsVectorLayer)
from qgis.PyQt.QtCore import QCoreApplication

from .. import runner

# The GeoPackage layers roofsweep writes for a LoD2 model (io/citymodel);
# building_parts only when a building has parts (footprints roofed by
# several solids), and load_gpkg_layers skips a layer the file lacks.
CITYMODEL_LAYERS = ("buildings", "building_parts", "roof_surfaces", "wall_surfaces", "ground_surfaces")
LINES_LAYERS = ("lines3d",)


class RoofsweepAlgorithm(QgsProcessingAlgorithm):
    """One roofsweep subcommand. Subclasses set COMMAND, NAME, DISPLAY and HELP."""

    COMMAND = None
    NAME = None
    DISPLAY = None
    HELP = ""
    # Options of the program this algorithm passes; checked against
    # `roofsweep COMMAND --help` before the run.
    USES_OPTIONS = ()

    def tr(self, text):
        return QCoreApplication.translate("roofsweep", text)

    def createInstance(self):
        return type(self)()

    def name(self):
        return self.NAME

    def displayName(self):
        return self.tr(self.DISPLAY)

    def group(self):
        return self.tr("roofsweep")

    def groupId(self):
        return "roofsweep"

    def shortHelpString(self):
        return self.tr(self.HELP + "\n\nRuns: roofsweep {}".format(self.COMMAND))

    # -- running the program ------------------------------------------------

    def program(self):
        """The roofsweep executable, after checking that it has this subcommand."""
        exe = runner.find_executable()
        runner.require_command(exe, self.COMMAND, self.USES_OPTIONS)
        return exe

    def run_program(self, args, feedback, capture_stdout=False):
        exe = self.program()
        return runner.run(exe, [self.COMMAND] + list(args), feedback, capture_stdout=capture_stdout)

    # -- parameter helpers ----------------------------------------------------

    @staticmethod
    def given(parameters, name):
        """True when an optional parameter was set (absent and None mean unset)."""
        v = parameters.get(name)
        return v is not None and v != ""

    @staticmethod
    def crs_argument(crs):
        """-a_srs value for a QGIS CRS: its authority id, else WKT2."""
        if not crs.isValid():
            return None
        if crs.authid():
            return crs.authid()
        return crs.toWkt(QgsCoordinateReferenceSystem.WKT_PREFERRED)

    def aoi_arguments(self, parameters, name, block, context):
        """-aoi for an extent parameter, in the block's CRS (roofsweep takes the tile in it)."""
        if not self.given(parameters, name):
            return []
        with open(block) as f:
            crs = QgsCoordinateReferenceSystem(json.load(f).get("crs") or "")
        rect = self.parameterAsExtent(parameters, name, context, crs if crs.isValid() else None)
        return ["-aoi", ",".join(repr(v) for v in (rect.xMinimum(), rect.yMinimum(),
                                                    rect.xMaximum(), rect.yMaximum()))]

    @staticmethod
    def existing_file(path, what):
        if not path or not os.path.exists(path):
            raise QgsProcessingException("{} '{}' does not exist".format(what, path or ""))
        return path

    # -- loading outputs ------------------------------------------------------

    def load_gpkg_layers(self, path, layer_names, context, output_name):
        """Adds the named layers of a GeoPackage to the project on completion.

        Returns their data source URIs (`path|layername=...`) in the order
        given; a layer the file lacks is reported and skipped.
        """
        uris = []
        base = os.path.splitext(os.path.basename(path))[0]
        for lname in layer_names:
            uri = "{}|layername={}".format(path, lname)
            layer = QgsVectorLayer(uri, "{} {}".format(base, lname), "ogr")
            if not layer.isValid():
                continue
            uris.append(uri)
            context.temporaryLayerStore().addMapLayer(layer)
            context.addLayerToLoadOnCompletion(
                layer.id(), QgsProcessingContext.LayerDetails(layer.name(), context.project(), output_name))
        return uris
