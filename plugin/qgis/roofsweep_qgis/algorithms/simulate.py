"""Simulate aerial block: roofsweep simulate."""

import os

from qgis.core import (QgsProcessingException, QgsProcessingOutputFile, QgsProcessingOutputNumber,
                       QgsProcessingParameterBoolean, QgsProcessingParameterCrs, QgsProcessingParameterEnum,
                       QgsProcessingParameterFile, QgsProcessingParameterFolderDestination,
                       QgsProcessingParameterNumber, QgsProcessingParameterString)

from .base import RoofsweepAlgorithm

PRESETS = ("easy", "realistic", "hard", "bench")
IMAGE_FORMATS = ("preset default", "jpg", "tif", "png")


class SimulateAlgorithm(RoofsweepAlgorithm):
    COMMAND = "simulate"
    NAME = "simulate"
    DISPLAY = "Simulate aerial block"
    HELP = ("Renders an oriented aerial block of LoD2 buildings with exactly known cameras and writes images, "
            "orientation, a block manifest (block.json), the ground truth (groundtruth.gml, groundtruth_edges.json) "
            "and the buildings' footprints (footprints.gpkg) into the output "
            "folder. A terrain slope puts the town on a hillside, a terrain relief on smooth hills and hollows; "
            "either gives the block a DTM (dtm.tif) instead of one ground height. Unset numbers take the preset's value. An existing output folder is replaced only if it "
            "is empty or an earlier simulation.")
    USES_OPTIONS = ("-preset", "-seed", "-o", "-overwrite")

    PRESET = "PRESET"
    SEED = "SEED"
    CITYGML = "CITYGML"
    CRS = "CRS"
    ORIGIN = "ORIGIN"
    IMAGE_FORMAT = "IMAGE_FORMAT"
    STRIPS = "STRIPS"
    VIEWS = "VIEWS"
    SIZE = "SIZE"
    GSD = "GSD"
    BUILDINGS = "BUILDINGS"
    OBLIQUES = "OBLIQUES"
    TERRAIN_SLOPE = "TERRAIN_SLOPE"
    TERRAIN_ASPECT = "TERRAIN_ASPECT"
    TERRAIN_RELIEF = "TERRAIN_RELIEF"
    OUTPUT = "OUTPUT"
    BLOCK = "BLOCK"
    GROUNDTRUTH = "GROUNDTRUTH"
    VIEW_COUNT = "VIEW_COUNT"
    BUILDING_COUNT = "BUILDING_COUNT"

    # (parameter, option, label, integer?, minimum)
    _NUMBERS = ((STRIPS, "-strips", "Flight strips", True, 1), (VIEWS, "-views", "Images per strip", True, 1),
                (SIZE, "-size", "Image size (pixels, square)", True, 16),
                (GSD, "-gsd", "Ground sample distance (m)", False, 0.001),
                (BUILDINGS, "-buildings", "Generated buildings", True, 1),
                (TERRAIN_SLOPE, "-terrain_slope", "Terrain slope (%)", False, 0),
                (TERRAIN_ASPECT, "-terrain_aspect", "Direction the terrain falls towards (degrees from north)",
                 False, -360),
                (TERRAIN_RELIEF, "-terrain_relief", "Terrain relief: height span of hills and hollows (m)", False,
                 0))

    def initAlgorithm(self, config=None):
        self.addParameter(QgsProcessingParameterEnum(self.PRESET, self.tr("Preset"), options=list(PRESETS),
                                                     defaultValue=1))
        self.addParameter(QgsProcessingParameterNumber(self.SEED, self.tr("Random seed"),
                                                       QgsProcessingParameterNumber.Integer, 1, False, 0))
        self.addParameter(QgsProcessingParameterFile(
            self.CITYGML, self.tr("Render this LoD2 model instead of a generated scene"), optional=True))
        self.addParameter(QgsProcessingParameterCrs(self.CRS, self.tr("CRS of a generated scene"),
                                                    optional=True))
        self.addParameter(QgsProcessingParameterString(self.ORIGIN, self.tr("Scene centre E,N,H"),
                                                       optional=True))
        self.addParameter(QgsProcessingParameterEnum(self.IMAGE_FORMAT, self.tr("Image format"),
                                                     options=list(IMAGE_FORMATS), defaultValue=0))
        for name, _, label, integer, minimum in self._NUMBERS:
            kind = QgsProcessingParameterNumber.Integer if integer else QgsProcessingParameterNumber.Double
            self.addParameter(QgsProcessingParameterNumber(name, self.tr(label), kind, None, True, minimum))
        self.addParameter(QgsProcessingParameterBoolean(self.OBLIQUES, self.tr("Add oblique views"),
                                                        defaultValue=False))
        self.addParameter(QgsProcessingParameterFolderDestination(self.OUTPUT, self.tr("Output folder")))
        self.addOutput(QgsProcessingOutputFile(self.BLOCK, self.tr("Block manifest")))
        self.addOutput(QgsProcessingOutputFile(self.GROUNDTRUTH, self.tr("Ground truth (CityGML)")))
        self.addOutput(QgsProcessingOutputNumber(self.VIEW_COUNT, self.tr("Views")))
        self.addOutput(QgsProcessingOutputNumber(self.BUILDING_COUNT, self.tr("Buildings")))

    def processAlgorithm(self, parameters, context, feedback):
        out = self.parameterAsString(parameters, self.OUTPUT, context)
        args = ["-preset", PRESETS[self.parameterAsEnum(parameters, self.PRESET, context)],
                "-seed", str(self.parameterAsInt(parameters, self.SEED, context))]
        if self.given(parameters, self.CITYGML):
            args += ["-citygml", self.existing_file(self.parameterAsFile(parameters, self.CITYGML, context),
                                                    "Model")]
        if self.given(parameters, self.CRS):
            srs = self.crs_argument(self.parameterAsCrs(parameters, self.CRS, context))
            if srs:
                args += ["-a_srs", srs]
        if self.given(parameters, self.ORIGIN):
            args += ["-origin", self.parameterAsString(parameters, self.ORIGIN, context).replace(" ", "")]
        fmt = self.parameterAsEnum(parameters, self.IMAGE_FORMAT, context)
        if fmt:
            args += ["-if", IMAGE_FORMATS[fmt]]
        for name, option, _, integer, _ in self._NUMBERS:
            if self.given(parameters, name):
                value = (self.parameterAsInt if integer else self.parameterAsDouble)(parameters, name, context)
                args += [option, repr(value)]
        if self.parameterAsBoolean(parameters, self.OBLIQUES, context):
            args.append("-obliques")
        if self._may_replace(out):
            args.append("-overwrite")
        args += ["-o", out]
        self.run_program(args, feedback)

        result = {self.OUTPUT: out, self.BLOCK: os.path.join(out, "block.json"),
                  self.GROUNDTRUTH: os.path.join(out, "groundtruth.gml")}
        summary = os.path.join(out, "simulation.json")
        if os.path.exists(summary):
            import json

            with open(summary) as f:
                s = json.load(f)
            result[self.VIEW_COUNT] = s.get("views")
            result[self.BUILDING_COUNT] = s.get("buildings")
        return result

    @staticmethod
    def _may_replace(folder):
        """-overwrite deletes the folder: allow it only for an empty one or an earlier simulation."""
        if not os.path.exists(folder):
            return False
        if not os.path.isdir(folder):
            raise QgsProcessingException("Output folder '{}' is a file".format(folder))
        if not os.listdir(folder) or os.path.exists(os.path.join(folder, "simulation.json")):
            return True
        raise QgsProcessingException(
            "Output folder '{}' is not empty and holds no earlier simulation; roofsweep would delete it. "
            "Choose a new or empty folder.".format(folder))
