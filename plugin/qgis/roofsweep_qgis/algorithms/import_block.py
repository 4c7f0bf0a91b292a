"""Import oriented images: roofsweep import."""

from qgis.core import (QgsProcessingException, QgsProcessingParameterCrs, QgsProcessingParameterEnum,
                       QgsProcessingParameterFile, QgsProcessingParameterFileDestination,
                       QgsProcessingParameterNumber, QgsProcessingParameterRasterLayer)

from .base import RoofsweepAlgorithm

FORMATS = ("opk", "pix4d", "metashape", "colmap", "opensfm", "vgg")
FORMAT_LABELS = ("OPK text / CSV / orthority GeoJSON (opk)", "Pix4D (pix4d)", "Agisoft Metashape (metashape)",
                 "COLMAP text model (colmap)", "OpenSfM reconstruction.json (opensfm)", "Oxford VGG (vgg)")


class ImportAlgorithm(RoofsweepAlgorithm):
    COMMAND = "import"
    NAME = "import"
    DISPLAY = "Import oriented images"
    HELP = ("Reads an oriented image block (exterior and interior orientation from COLMAP, Pix4D, Metashape, "
            "OPK text, OpenSfM or Oxford VGG) into a roofsweep block manifest (block.json). Give the source "
            "as a file or, for folder-based formats (COLMAP sparse model, VGG sequence), as a folder.")
    USES_OPTIONS = ("-o", "-a_srs", "-camera", "-images", "-ground", "-dtm", "-dsm", "-overwrite")

    FORMAT = "FORMAT"
    SOURCE = "SOURCE"
    SOURCE_FOLDER = "SOURCE_FOLDER"
    CAMERA = "CAMERA"
    IMAGES = "IMAGES"
    CRS = "CRS"
    GROUND = "GROUND"
    DTM = "DTM"
    DSM = "DSM"
    OUTPUT = "OUTPUT"

    def initAlgorithm(self, config=None):
        self.addParameter(QgsProcessingParameterEnum(self.FORMAT, self.tr("Orientation format"),
                                                     options=[self.tr(x) for x in FORMAT_LABELS], defaultValue=0))
        self.addParameter(QgsProcessingParameterFile(self.SOURCE, self.tr("Orientation file"), optional=True))
        self.addParameter(QgsProcessingParameterFile(self.SOURCE_FOLDER, self.tr("Orientation folder"),
                                                     behavior=QgsProcessingParameterFile.Folder, optional=True))
        self.addParameter(QgsProcessingParameterFile(self.CAMERA, self.tr("Camera file (interior orientation)"),
                                                     optional=True))
        self.addParameter(QgsProcessingParameterFile(self.IMAGES, self.tr("Image folder"),
                                                     behavior=QgsProcessingParameterFile.Folder, optional=True))
        self.addParameter(QgsProcessingParameterCrs(self.CRS, self.tr("CRS of the positions (when the source has "
                                                                      "none)"), optional=True))
        self.addParameter(QgsProcessingParameterNumber(self.GROUND, self.tr("Ground height (ellipsoidal)"),
                                                       QgsProcessingParameterNumber.Double, None, True))
        self.addParameter(QgsProcessingParameterRasterLayer(self.DTM, self.tr("Ground model (DTM)"),
                                                            optional=True))
        self.addParameter(QgsProcessingParameterRasterLayer(
            self.DSM, self.tr("Surface model (DSM; the ground is derived from it), instead of a DTM"),
            optional=True))
        self.addParameter(QgsProcessingParameterFileDestination(self.OUTPUT, self.tr("Block manifest"),
                                                                fileFilter="Block manifest (*.json)"))

    def processAlgorithm(self, parameters, context, feedback):
        fmt = FORMATS[self.parameterAsEnum(parameters, self.FORMAT, context)]
        sources = [self.parameterAsFile(parameters, p, context)
                   for p in (self.SOURCE, self.SOURCE_FOLDER) if self.given(parameters, p)]
        if len(sources) != 1:
            raise QgsProcessingException("Give the orientation as a file or as a folder (exactly one of them)")
        out = self.parameterAsFileOutput(parameters, self.OUTPUT, context)
        args = [fmt, self.existing_file(sources[0], "Orientation source")]
        if self.given(parameters, self.CAMERA):
            args += ["-camera", self.existing_file(self.parameterAsFile(parameters, self.CAMERA, context),
                                                   "Camera file")]
        if self.given(parameters, self.IMAGES):
            args += ["-images", self.parameterAsFile(parameters, self.IMAGES, context)]
        if self.given(parameters, self.CRS):
            srs = self.crs_argument(self.parameterAsCrs(parameters, self.CRS, context))
            if srs:
                args += ["-a_srs", srs]
        if self.given(parameters, self.GROUND):
            args += ["-ground", repr(self.parameterAsDouble(parameters, self.GROUND, context))]
        if self.given(parameters, self.DTM):
            dtm = self.parameterAsRasterLayer(parameters, self.DTM, context)
            if dtm is None:
                raise QgsProcessingException("Cannot open the ground model '{}'".format(parameters[self.DTM]))
            args += ["-dtm", dtm.source()]
        if self.given(parameters, self.DSM):
            dsm = self.parameterAsRasterLayer(parameters, self.DSM, context)
            if dsm is None:
                raise QgsProcessingException("Cannot open the surface model '{}'".format(parameters[self.DSM]))
            args += ["-dsm", dsm.source()]
        args += ["-overwrite", "-o", out]
        self.run_program(args, feedback)
        return {self.OUTPUT: out}
