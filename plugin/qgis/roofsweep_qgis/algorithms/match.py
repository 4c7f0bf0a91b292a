"""Reconstruct 3D lines: roofsweep match."""

from qgis.core import (QgsProcessingOutputMultipleLayers, QgsProcessingParameterFile,
                       QgsProcessingParameterFileDestination)

from .base import LINES_LAYERS, RoofsweepAlgorithm


class MatchAlgorithm(RoofsweepAlgorithm):
    COMMAND = "match"
    NAME = "match"
    DISPLAY = "Reconstruct 3D lines"
    HELP = ("Matches the line segments of all views of a block into 3D lines (colour-aware matching, Scholze "
            "2000) and writes them to a GeoPackage layer lines3d, which is added to the project.")
    USES_OPTIONS = ("-segments", "-o", "-overwrite")

    BLOCK = "BLOCK"
    SEGMENTS = "SEGMENTS"
    OUTPUT = "OUTPUT"
    LAYERS = "LAYERS"

    def initAlgorithm(self, config=None):
        self.addParameter(QgsProcessingParameterFile(self.BLOCK, self.tr("Block manifest"),
                                                     fileFilter="Block manifest (*.json)"))
        self.addParameter(QgsProcessingParameterFile(
            self.SEGMENTS, self.tr("Segments folder (from Extract line segments)"),
            behavior=QgsProcessingParameterFile.Folder))
        self.addParameter(QgsProcessingParameterFileDestination(self.OUTPUT, self.tr("3D lines"),
                                                                fileFilter="GeoPackage (*.gpkg)"))
        self.addOutput(QgsProcessingOutputMultipleLayers(self.LAYERS, self.tr("Loaded layers")))

    def processAlgorithm(self, parameters, context, feedback):
        block = self.existing_file(self.parameterAsFile(parameters, self.BLOCK, context), "Block")
        segments = self.existing_file(self.parameterAsFile(parameters, self.SEGMENTS, context), "Segments folder")
        out = self.parameterAsFileOutput(parameters, self.OUTPUT, context)
        self.run_program([block, "-segments", segments, "-overwrite", "-o", out], feedback)
        layers = self.load_gpkg_layers(out, LINES_LAYERS, context, self.OUTPUT)
        return {self.OUTPUT: out, self.LAYERS: layers}
