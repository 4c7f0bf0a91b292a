"""Describe oriented block: roofsweep info."""

import json

from qgis.core import (QgsProcessingOutputNumber, QgsProcessingOutputString, QgsProcessingParameterFile,
                       QgsProcessingParameterFileDestination)

from .base import RoofsweepAlgorithm


class InfoAlgorithm(RoofsweepAlgorithm):
    COMMAND = "info"
    NAME = "info"
    DISPLAY = "Describe oriented block"
    HELP = ("Describes a block manifest: images, cameras, CRS, ground sample distance per image, overlaps and "
            "warnings. Writes the description as JSON and reports the image count and mean GSD.")
    USES_OPTIONS = ("--json",)

    BLOCK = "BLOCK"
    OUTPUT = "OUTPUT"
    IMAGES = "IMAGES"
    MEAN_GSD = "MEAN_GSD"
    CRS = "CRS"

    def initAlgorithm(self, config=None):
        self.addParameter(QgsProcessingParameterFile(self.BLOCK, self.tr("Block manifest"),
                                                     fileFilter="Block manifest (*.json)"))
        self.addParameter(QgsProcessingParameterFileDestination(self.OUTPUT, self.tr("Description (JSON)"),
                                                                fileFilter="JSON (*.json)", optional=True,
                                                                createByDefault=False))
        self.addOutput(QgsProcessingOutputNumber(self.IMAGES, self.tr("Images")))
        self.addOutput(QgsProcessingOutputNumber(self.MEAN_GSD, self.tr("Mean GSD (m)")))
        self.addOutput(QgsProcessingOutputString(self.CRS, self.tr("CRS")))

    def processAlgorithm(self, parameters, context, feedback):
        block = self.existing_file(self.parameterAsFile(parameters, self.BLOCK, context), "Block")
        text = self.run_program(["-q", "--json", block], feedback, capture_stdout=True)
        try:
            info = json.loads(text)
        except ValueError as e:
            from qgis.core import QgsProcessingException

            raise QgsProcessingException("roofsweep info printed no JSON ({}): {}".format(e, text[:200]))
        images = info.get("images", [])
        gsds = [i["gsd_m"] for i in images if isinstance(i.get("gsd_m"), (int, float))]
        result = {self.IMAGES: len(images), self.MEAN_GSD: sum(gsds) / len(gsds) if gsds else None,
                  self.CRS: _crs_text(info)}
        feedback.pushInfo("{} images, mean GSD {}".format(
            len(images), "{:.3f} m".format(result[self.MEAN_GSD]) if gsds else "unknown"))
        out = self.parameterAsFileOutput(parameters, self.OUTPUT, context)
        if out:
            with open(out, "w") as f:
                json.dump(info, f, indent=2)
            result[self.OUTPUT] = out
        return result


def _crs_text(info):
    crs = info.get("crs")
    if isinstance(crs, dict):
        return crs.get("name") or crs.get("id") or json.dumps(crs)
    return crs if isinstance(crs, str) else None
