"""Convert LoD2 model: roofsweep convert."""

from qgis.core import (QgsProcessingOutputMultipleLayers, QgsProcessingParameterBoolean,
                       QgsProcessingParameterCrs, QgsProcessingParameterEnum, QgsProcessingParameterFile,
                       QgsProcessingParameterFileDestination)

from .base import CITYMODEL_LAYERS, RoofsweepAlgorithm

# Display name, -of value ("" = follow the output extension).
FORMATS = (("From output file extension", ""), ("GeoPackage", "GPKG"), ("CityGML 2.0", "CityGML"),
           ("CityJSON 2.0", "CityJSON"), ("CityJSONSeq", "CityJSONSeq"), ("FlatGeobuf", "FlatGeobuf"),
           ("GeoJSON", "GeoJSON"))
OUTPUT_FILTER = ("GeoPackage (*.gpkg);;CityGML (*.gml);;CityJSON (*.city.json *.json);;"
                 "CityJSONSeq (*.city.jsonl *.jsonl);;FlatGeobuf (*.fgb);;GeoJSON (*.geojson)")


class ConvertAlgorithm(RoofsweepAlgorithm):
    COMMAND = "convert"
    NAME = "convert"
    DISPLAY = "Convert LoD2 model"
    HELP = ("Converts a LoD2 building model between CityGML 2.0, CityJSON 2.0, CityJSONSeq, GeoPackage and "
            "other OGR vector formats. GeoPackage output has the layers buildings, roof_surfaces, "
            "wall_surfaces and ground_surfaces (3D multipolygons), which are added to the project.")
    USES_OPTIONS = ("-of", "-a_srs", "-overwrite", "-allow_empty", "-no_check")

    INPUT = "INPUT"
    FORMAT = "FORMAT"
    CRS = "CRS"
    NO_CHECK = "NO_CHECK"
    ALLOW_EMPTY = "ALLOW_EMPTY"
    OUTPUT = "OUTPUT"
    LAYERS = "LAYERS"

    def initAlgorithm(self, config=None):
        self.addParameter(QgsProcessingParameterFile(
            self.INPUT, self.tr("Input model (CityGML, CityJSON, CityJSONSeq, GeoPackage)")))
        self.addParameter(QgsProcessingParameterEnum(
            self.FORMAT, self.tr("Output format"), options=[self.tr(f[0]) for f in FORMATS], defaultValue=0))
        self.addParameter(QgsProcessingParameterCrs(
            self.CRS, self.tr("Assign CRS (no reprojection)"), optional=True))
        self.addParameter(QgsProcessingParameterBoolean(
            self.NO_CHECK, self.tr("Skip the solid checks (roofsweep_validity)"), defaultValue=False))
        self.addParameter(QgsProcessingParameterBoolean(
            self.ALLOW_EMPTY, self.tr("Allow a model without buildings"), defaultValue=False))
        self.addParameter(QgsProcessingParameterFileDestination(
            self.OUTPUT, self.tr("Output model"), fileFilter=OUTPUT_FILTER))
        self.addOutput(QgsProcessingOutputMultipleLayers(self.LAYERS, self.tr("Loaded layers")))

    def processAlgorithm(self, parameters, context, feedback):
        src = self.existing_file(self.parameterAsFile(parameters, self.INPUT, context), "Input model")
        dst = self.parameterAsFileOutput(parameters, self.OUTPUT, context)
        fmt = FORMATS[self.parameterAsEnum(parameters, self.FORMAT, context)][1]
        args = []
        if fmt:
            args += ["-of", fmt]
        if self.given(parameters, self.CRS):
            srs = self.crs_argument(self.parameterAsCrs(parameters, self.CRS, context))
            if srs:
                args += ["-a_srs", srs]
        if self.parameterAsBoolean(parameters, self.NO_CHECK, context):
            args.append("-no_check")
        if self.parameterAsBoolean(parameters, self.ALLOW_EMPTY, context):
            args.append("-allow_empty")
        # QGIS already asked before replacing a chosen file.
        args += ["-overwrite", src, dst]
        self.run_program(args, feedback)

        layers = []
        if fmt == "GPKG" or (not fmt and dst.lower().endswith(".gpkg")):
            layers = self.load_gpkg_layers(dst, CITYMODEL_LAYERS, context, self.OUTPUT)
        return {self.OUTPUT: dst, self.LAYERS: layers}
