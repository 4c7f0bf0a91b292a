"""Reconstruct LoD2 buildings: roofsweep run (the whole pipeline)."""

from qgis.core import (QgsProcessingOutputMultipleLayers, QgsProcessingParameterFile,
                       QgsProcessingParameterFileDestination)

from .base import CITYMODEL_LAYERS, LINES_LAYERS, RoofsweepAlgorithm
from .convert import OUTPUT_FILTER


class ReconstructAlgorithm(RoofsweepAlgorithm):
    COMMAND = "run"
    NAME = "run"
    DISPLAY = "Reconstruct LoD2 buildings"
    HELP = ("Runs the whole pipeline on an oriented block: line segments, 3D lines, plane sweep, LoD2 "
            "buildings. The output format follows the extension (GeoPackage, CityGML, CityJSON); GeoPackage "
            "layers are added to the project.")
    USES_OPTIONS = ("-o", "-overwrite")

    BLOCK = "BLOCK"
    OUTPUT = "OUTPUT"
    LAYERS = "LAYERS"

    def initAlgorithm(self, config=None):
        self.addParameter(QgsProcessingParameterFile(self.BLOCK, self.tr("Block manifest"),
                                                     fileFilter="Block manifest (*.json)"))
        self.addParameter(QgsProcessingParameterFileDestination(self.OUTPUT, self.tr("LoD2 buildings"),
                                                                fileFilter=OUTPUT_FILTER))
        self.addOutput(QgsProcessingOutputMultipleLayers(self.LAYERS, self.tr("Loaded layers")))

    def processAlgorithm(self, parameters, context, feedback):
        block = self.existing_file(self.parameterAsFile(parameters, self.BLOCK, context), "Block")
        out = self.parameterAsFileOutput(parameters, self.OUTPUT, context)
        self.run_program([block, "-overwrite", "-o", out], feedback)
        layers = []
        if out.lower().endswith(".gpkg"):
            layers = self.load_gpkg_layers(out, CITYMODEL_LAYERS + LINES_LAYERS, context, self.OUTPUT)
        return {self.OUTPUT: out, self.LAYERS: layers}
