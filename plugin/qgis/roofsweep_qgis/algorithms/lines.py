"""Extract line segments: roofsweep lines."""

from qgis.core import QgsProcessingParameterFile, QgsProcessingParameterFolderDestination

from .base import RoofsweepAlgorithm


class LinesAlgorithm(RoofsweepAlgorithm):
    COMMAND = "lines"
    NAME = "lines"
    DISPLAY = "Extract line segments"
    HELP = ("Extracts colour edges and straight line segments (Scholze 2000) from every image of a block and "
            "writes them, one segments file per view, into the output folder.")
    USES_OPTIONS = ("-o", "-overwrite")

    BLOCK = "BLOCK"
    OUTPUT = "OUTPUT"

    def initAlgorithm(self, config=None):
        self.addParameter(QgsProcessingParameterFile(self.BLOCK, self.tr("Block manifest"),
                                                     fileFilter="Block manifest (*.json)"))
        self.addParameter(QgsProcessingParameterFolderDestination(self.OUTPUT, self.tr("Segments folder")))

    def processAlgorithm(self, parameters, context, feedback):
        block = self.existing_file(self.parameterAsFile(parameters, self.BLOCK, context), "Block")
        out = self.parameterAsString(parameters, self.OUTPUT, context)
        self.run_program([block, "-overwrite", "-o", out], feedback)
        return {self.OUTPUT: out}
