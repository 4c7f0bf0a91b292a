"""Extract line segments: roofsweep lines."""

from qgis.core import (QgsProcessingParameterEnum, QgsProcessingParameterExtent, QgsProcessingParameterFile,
                       QgsProcessingParameterFileDestination, QgsProcessingParameterFolderDestination,
                       QgsProcessingParameterNumber)

from .base import RoofsweepAlgorithm

METHODS = ("max", "dizenzo", "grey")


class LinesAlgorithm(RoofsweepAlgorithm):
    COMMAND = "lines"
    NAME = "lines"
    DISPLAY = "Extract line segments"
    HELP = ("Extracts straight colour edge segments (Scholze 2000) from every image of a block and writes one "
            "LineString layer per image (lines_<image>) in image pixel coordinates (x right, y down, origin at "
            "the top-left corner; no CRS). The layers are not added to the map, which is georeferenced. "
            "With a tile extent, only the images that see it (and 30 m around it) are read, each in the "
            "window that does, as for the reconstruction; the coordinates stay those of the whole image.")
    USES_OPTIONS = ("-o", "-method", "-min-length", "-png", "-aoi", "-overwrite")

    BLOCK = "BLOCK"
    METHOD = "METHOD"
    MIN_LENGTH = "MIN_LENGTH"
    PNG = "PNG"
    EXTENT = "EXTENT"
    OUTPUT = "OUTPUT"

    def initAlgorithm(self, config=None):
        self.addParameter(QgsProcessingParameterFile(self.BLOCK, self.tr("Block manifest"),
                                                     fileFilter="Block manifest (*.json)"))
        self.addParameter(QgsProcessingParameterEnum(self.METHOD, self.tr("Gradient fusion of the colour bands"),
                                                     options=list(METHODS), defaultValue=0))
        self.addParameter(QgsProcessingParameterNumber(self.MIN_LENGTH, self.tr("Shortest segment kept (pixels)"),
                                                       QgsProcessingParameterNumber.Double, 15.0, False, 2.0))
        self.addParameter(QgsProcessingParameterFolderDestination(self.PNG, self.tr("Overlay images folder"),
                                                                  optional=True, createByDefault=False))
        self.addParameter(QgsProcessingParameterExtent(
            self.EXTENT, self.tr("Tile: read only what the images see of this extent"), optional=True))
        self.addParameter(QgsProcessingParameterFileDestination(self.OUTPUT, self.tr("Segments"),
                                                                fileFilter="GeoPackage (*.gpkg)"))

    def processAlgorithm(self, parameters, context, feedback):
        block = self.existing_file(self.parameterAsFile(parameters, self.BLOCK, context), "Block")
        out = self.parameterAsFileOutput(parameters, self.OUTPUT, context)
        args = [block, "-method", METHODS[self.parameterAsEnum(parameters, self.METHOD, context)],
                "-min-length", repr(self.parameterAsDouble(parameters, self.MIN_LENGTH, context))]
        png = self.parameterAsString(parameters, self.PNG, context) if self.given(parameters, self.PNG) else ""
        if png:
            args += ["-png", png]
        args += self.aoi_arguments(parameters, self.EXTENT, block, context)
        args += ["-overwrite", "-o", out]
        self.run_program(args, feedback)
        result = {self.OUTPUT: out}
        if png:
            result[self.PNG] = png
        return result
