"""Reconstruct 3D lines: roofsweep match."""

from qgis.core import (QgsProcessingOutputMultipleLayers, QgsProcessingParameterExtent,
                       QgsProcessingParameterFile, QgsProcessingParameterFileDestination)

from .base import LINES_LAYERS, RoofsweepAlgorithm


class MatchAlgorithm(RoofsweepAlgorithm):
    COMMAND = "match"
    NAME = "match"
    DISPLAY = "Reconstruct 3D lines"
    HELP = ("Matches straight colour edge segments across the views of a block into 3D lines (Scholze 2000: "
            "geometric, chromatic and correlation tests, multi-view verification, least-squares lines) and "
            "writes a LineStringZ layer lines3d, which is added to the project. With the ground-truth edges "
            "of a simulation the log also reports true-pair counts and line scores. With a tile extent, "
            "only the images and image windows that see it (and 30 m around it) are read, as for the "
            "reconstruction; the ground truth then cannot be given.")
    USES_OPTIONS = ("-o", "-truth", "-aoi", "-overwrite")

    BLOCK = "BLOCK"
    TRUTH = "TRUTH"
    OUTPUT = "OUTPUT"
    EXTENT = "EXTENT"
    LAYERS = "LAYERS"

    def initAlgorithm(self, config=None):
        self.addParameter(QgsProcessingParameterFile(self.BLOCK, self.tr("Block manifest"),
                                                     fileFilter="Block manifest (*.json)"))
        self.addParameter(QgsProcessingParameterFile(
            self.TRUTH, self.tr("Ground-truth edges of a simulation (groundtruth_edges.json)"), optional=True,
            fileFilter="JSON (*.json)"))
        self.addParameter(QgsProcessingParameterExtent(
            self.EXTENT, self.tr("Tile: match only what the images see of this extent"), optional=True))
        self.addParameter(QgsProcessingParameterFileDestination(self.OUTPUT, self.tr("3D lines"),
                                                                fileFilter="GeoPackage (*.gpkg)"))
        self.addOutput(QgsProcessingOutputMultipleLayers(self.LAYERS, self.tr("Loaded layers")))

    def processAlgorithm(self, parameters, context, feedback):
        block = self.existing_file(self.parameterAsFile(parameters, self.BLOCK, context), "Block")
        out = self.parameterAsFileOutput(parameters, self.OUTPUT, context)
        args = [block]
        if self.given(parameters, self.TRUTH):
            args += ["-truth", self.existing_file(self.parameterAsFile(parameters, self.TRUTH, context),
                                                  "Ground-truth edges")]
        args += self.aoi_arguments(parameters, self.EXTENT, block, context)
        args += ["-overwrite", "-o", out]
        self.run_program(args, feedback)
        layers = []
        if out.lower().endswith(".gpkg"):
            layers = self.load_gpkg_layers(out, LINES_LAYERS, context, self.OUTPUT)
        return {self.OUTPUT: out, self.LAYERS: layers}
