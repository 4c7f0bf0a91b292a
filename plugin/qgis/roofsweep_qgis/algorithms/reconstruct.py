"""Reconstruct LoD2 buildings: roofsweep run (the whole pipeline)."""

from qgis.core import (QgsProcessing, QgsProcessingOutputMultipleLayers, QgsProcessingParameterBoolean,
                       QgsProcessingParameterDefinition,
                       QgsProcessingParameterFeatureSource, QgsProcessingParameterField,
                       QgsProcessingParameterFile, QgsProcessingParameterFileDestination,
                       QgsProcessingParameterExtent, QgsProcessingParameterNumber)

from .base import CITYMODEL_LAYERS, LINES_LAYERS, RoofsweepAlgorithm
from .convert import OUTPUT_FILTER


class ReconstructAlgorithm(RoofsweepAlgorithm):
    COMMAND = "run"
    NAME = "run"
    DISPLAY = "Reconstruct LoD2 buildings"
    HELP = ("Runs the whole pipeline on an oriented block: line segments, 3D lines, plane sweep, LoD2 "
            "buildings. The output format follows the extension (GeoPackage, CityGML, CityJSON); GeoPackage "
            "layers are added to the project. Optional building footprints (any polygon layer) restrict "
            "the reconstruction: walls stand on the footprint where the roof planes cover it, and each "
            "building carries its footprint's id; a footprint whose roof was not reconstructed gets an LoD1 "
            "block (field lod = 1, lod1_reason) at the height of the 3D lines over it, unless unticked. "
            "With a tile extent, only the images and image windows "
            "that see it (and 30 m around it) are read, and only the buildings whose ground centre lies in "
            "it are written, ids prefixed with the tile's corner: the tiles of a grid hold every building once.")
    USES_OPTIONS = ("-o", "-overwrite", "-report", "-planes", "-min_height", "-footprints",
                    "-footprints_layer", "-footprints_id", "-no_lod1", "-aoi")

    BLOCK = "BLOCK"
    OUTPUT = "OUTPUT"
    REPORT = "REPORT"
    PLANES = "PLANES"
    MIN_HEIGHT = "MIN_HEIGHT"
    FOOTPRINTS = "FOOTPRINTS"
    FOOTPRINT_ID = "FOOTPRINT_ID"
    LOD1 = "LOD1"
    EXTENT = "EXTENT"
    LAYERS = "LAYERS"

    def initAlgorithm(self, config=None):
        self.addParameter(QgsProcessingParameterFile(self.BLOCK, self.tr("Block manifest"),
                                                     fileFilter="Block manifest (*.json)"))
        self.addParameter(QgsProcessingParameterFileDestination(self.OUTPUT, self.tr("LoD2 buildings"),
                                                                fileFilter=OUTPUT_FILTER))
        self.addParameter(QgsProcessingParameterFileDestination(
            self.REPORT, self.tr("Report: stage table and why each rejected plane or building was not built"),
            fileFilter="JSON (*.json)", optional=True, createByDefault=False))
        self.addParameter(QgsProcessingParameterFileDestination(
            self.PLANES, self.tr("Roof plane hypotheses: patch, score, built or why not"),
            fileFilter="GeoPackage (*.gpkg)", optional=True, createByDefault=False))
        self.addParameter(QgsProcessingParameterFeatureSource(
            self.FOOTPRINTS, self.tr("Building footprints"), [QgsProcessing.TypeVectorPolygon], optional=True))
        self.addParameter(QgsProcessingParameterField(
            self.FOOTPRINT_ID, self.tr("Footprint id field (default: id, identificatie, gml_id or fid)"),
            parentLayerParameterName=self.FOOTPRINTS, optional=True))
        self.addParameter(QgsProcessingParameterBoolean(
            self.LOD1, self.tr("LoD1 blocks over footprints whose roof was not reconstructed"), True))
        self.addParameter(QgsProcessingParameterExtent(
            self.EXTENT, self.tr("Tile: only the buildings whose ground centre lies in this extent"), optional=True))
        min_height = QgsProcessingParameterNumber(self.MIN_HEIGHT, self.tr("Lowest roof above the ground (m)"),
                                                  QgsProcessingParameterNumber.Double, 2.0, minValue=0.0)
        min_height.setFlags(min_height.flags() | QgsProcessingParameterDefinition.FlagAdvanced)
        self.addParameter(min_height)
        self.addOutput(QgsProcessingOutputMultipleLayers(self.LAYERS, self.tr("Loaded layers")))

    def processAlgorithm(self, parameters, context, feedback):
        block = self.existing_file(self.parameterAsFile(parameters, self.BLOCK, context), "Block")
        out = self.parameterAsFileOutput(parameters, self.OUTPUT, context)
        args = [block, "-overwrite", "-o", out,
                "-min_height", repr(self.parameterAsDouble(parameters, self.MIN_HEIGHT, context))]
        report = self.parameterAsFileOutput(parameters, self.REPORT, context) \
            if self.given(parameters, self.REPORT) else ""
        if report:
            args += ["-report", report]
        planes = self.parameterAsFileOutput(parameters, self.PLANES, context) \
            if self.given(parameters, self.PLANES) else ""
        if planes:
            args += ["-planes", planes]
        if self.given(parameters, self.FOOTPRINTS):
            # A layer roofsweep's OGR can open as it is, else a GeoPackage copy
            # (memory layers, selections, virtual layers).
            path, layer = self.parameterAsCompatibleSourceLayerPathAndLayerName(
                parameters, self.FOOTPRINTS, context, ["gpkg", "shp", "geojson", "fgb"], "gpkg", feedback)
            args += ["-footprints", path]
            if layer:
                args += ["-footprints_layer", layer]
            fields = self.parameterAsFields(parameters, self.FOOTPRINT_ID, context)
            if fields:
                args += ["-footprints_id", fields[0]]
            if not self.parameterAsBool(parameters, self.LOD1, context):
                args += ["-no_lod1"]
        args += self.aoi_arguments(parameters, self.EXTENT, block, context)
        self.run_program(args, feedback)
        layers = []
        if out.lower().endswith(".gpkg"):
            layers = self.load_gpkg_layers(out, CITYMODEL_LAYERS + LINES_LAYERS, context, self.OUTPUT)
        if planes:
            layers += self.load_gpkg_layers(planes, ("roof_planes",), context, self.PLANES)
        return {self.OUTPUT: out, self.REPORT: report, self.PLANES: planes, self.LAYERS: layers}
