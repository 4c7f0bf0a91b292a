"""Check a model against the images: roofsweep overlay."""

import json

from qgis.core import (QgsProcessingException, QgsProcessingOutputNumber, QgsProcessingParameterFile,
                       QgsProcessingParameterFileDestination, QgsProcessingParameterFolderDestination)

from .base import RoofsweepAlgorithm


class OverlayAlgorithm(RoofsweepAlgorithm):
    COMMAND = "overlay"
    NAME = "overlay"
    DISPLAY = "Check a model against the images"
    HELP = ("Draws a LoD2 model over every image of its block (roof edges green where an image edge runs along "
            "them, red where none does; walls cyan) into one PNG per image, and measures the share of the "
            "visible roof-edge length that lies on an image edge, per view and per building: the check of a "
            "reconstruction on real images, where there is no ground truth. The model may be in any CRS.")
    USES_OPTIONS = ("-o", "-report", "-overwrite")

    BLOCK = "BLOCK"
    MODEL = "MODEL"
    OUTPUT = "OUTPUT"
    REPORT = "REPORT"
    ON_EDGE = "ROOF_EDGES_ON_IMAGE_EDGES"

    def initAlgorithm(self, config=None):
        self.addParameter(QgsProcessingParameterFile(self.BLOCK, self.tr("Block manifest"),
                                                     fileFilter="Block manifest (*.json)"))
        self.addParameter(QgsProcessingParameterFile(self.MODEL, self.tr("LoD2 model (CityGML, CityJSON, "
                                                                         "GeoPackage)")))
        self.addParameter(QgsProcessingParameterFolderDestination(self.OUTPUT, self.tr("Overlay images folder")))
        self.addParameter(QgsProcessingParameterFileDestination(self.REPORT, self.tr("Report (JSON)"),
                                                                fileFilter="JSON (*.json)"))
        self.addOutput(QgsProcessingOutputNumber(self.ON_EDGE, self.tr("Share of the visible roof edges on an "
                                                                       "image edge")))

    def processAlgorithm(self, parameters, context, feedback):
        block = self.existing_file(self.parameterAsFile(parameters, self.BLOCK, context), "Block")
        model = self.existing_file(self.parameterAsFile(parameters, self.MODEL, context), "Model")
        out = self.parameterAsString(parameters, self.OUTPUT, context)
        report = self.parameterAsFileOutput(parameters, self.REPORT, context)
        self.run_program([block, model, "-o", out, "-report", report, "-overwrite"], feedback)
        try:
            with open(report) as f:
                doc = json.load(f)
        except (OSError, ValueError) as e:
            raise QgsProcessingException("roofsweep overlay wrote no report ({})".format(e))
        result = {self.OUTPUT: out, self.REPORT: report}
        value = doc.get("total", {}).get("supported_fraction")
        if isinstance(value, (int, float)):
            result[self.ON_EDGE] = value
        return result
