"""Evaluate against ground truth: roofsweep eval."""

import json

from qgis.core import (QgsProcessingException, QgsProcessingOutputMultipleLayers, QgsProcessingOutputNumber,
                       QgsProcessingParameterFile, QgsProcessingParameterFileDestination,
                       QgsProcessingParameterNumber)

from .base import RoofsweepAlgorithm


class EvaluateAlgorithm(RoofsweepAlgorithm):
    COMMAND = "eval"
    NAME = "eval"
    DISPLAY = "Evaluate against ground truth"
    HELP = ("Scores a LoD2 reconstruction against ground truth like the ISPRS benchmark (roof plane "
            "completeness, correctness and quality, normal-angle, vertex and height errors, buildings, roof "
            "types, optionally 3D lines). The ground truth may be a model or the groundtruth.gml of a "
            "simulation. Writes the report as JSON, and optionally the matched roof planes' vertices as a "
            "point layer (distance to the reference outline, and whether each lies on it, inside it, over "
            "another roof or over no roof), which is added to the project.")
    USES_OPTIONS = ("--json", "-lines", "-png", "-vertices", "-gsd", "-overwrite")

    # Output name -> (report section, key): the headline figures.
    FIGURES = {"ROOF_COMPLETENESS": ("roof_planes", "completeness"),
               "ROOF_CORRECTNESS": ("roof_planes", "correctness"),
               "ROOF_QUALITY": ("roof_planes", "quality"),
               "BUILDING_COMPLETENESS": ("buildings", "completeness"),
               "BUILDING_CORRECTNESS": ("buildings", "correctness"),
               "RMSZ_M": ("geometry", "rmsz_m"),
               "LINES_COMPLETENESS": ("lines3d", "completeness")}

    RESULT = "RESULT"
    GROUNDTRUTH = "GROUNDTRUTH"
    LINES = "LINES"
    GSD = "GSD"
    OUTPUT = "OUTPUT"
    PNG = "PNG"
    VERTICES = "VERTICES"
    LAYERS = "LAYERS"

    def initAlgorithm(self, config=None):
        self.addParameter(QgsProcessingParameterFile(self.RESULT, self.tr("Reconstructed model")))
        self.addParameter(QgsProcessingParameterFile(self.GROUNDTRUTH, self.tr("Ground-truth model")))
        self.addParameter(QgsProcessingParameterFile(self.LINES, self.tr("3D lines to score"), optional=True))
        self.addParameter(QgsProcessingParameterNumber(self.GSD, self.tr("GSD for the vertex RMS in pixels (m)"),
                                                       QgsProcessingParameterNumber.Double, None, True, 0.0))
        self.addParameter(QgsProcessingParameterFileDestination(self.OUTPUT, self.tr("Report (JSON)"),
                                                                fileFilter="JSON (*.json)"))
        self.addParameter(QgsProcessingParameterFileDestination(self.PNG, self.tr("Plan-view overlay"),
                                                                fileFilter="PNG (*.png)", optional=True,
                                                                createByDefault=False))
        self.addParameter(QgsProcessingParameterFileDestination(
            self.VERTICES, self.tr("Vertices against the reference outlines"), fileFilter="GeoPackage (*.gpkg)",
            optional=True, createByDefault=False))
        for name, (section, key) in self.FIGURES.items():
            self.addOutput(QgsProcessingOutputNumber(name, self.tr("{} {}".format(section, key))))
        self.addOutput(QgsProcessingOutputMultipleLayers(self.LAYERS, self.tr("Loaded layers")))

    def processAlgorithm(self, parameters, context, feedback):
        args = ["-q", "--json",
                self.existing_file(self.parameterAsFile(parameters, self.RESULT, context), "Result"),
                self.existing_file(self.parameterAsFile(parameters, self.GROUNDTRUTH, context), "Ground truth")]
        if self.given(parameters, self.LINES):
            args += ["-lines", self.existing_file(self.parameterAsFile(parameters, self.LINES, context), "Lines")]
        if self.given(parameters, self.GSD):
            args += ["-gsd", repr(self.parameterAsDouble(parameters, self.GSD, context))]
        png = self.parameterAsFileOutput(parameters, self.PNG, context)
        if png:
            args += ["-png", png]
        vertices = self.parameterAsFileOutput(parameters, self.VERTICES, context)
        if vertices:
            args += ["-vertices", vertices]
        if png or vertices:
            args.append("-overwrite")
        text = self.run_program(args, feedback, capture_stdout=True)
        try:
            report = json.loads(text)
        except ValueError as e:
            raise QgsProcessingException("roofsweep eval printed no JSON ({}): {}".format(e, text[:200]))
        out = self.parameterAsFileOutput(parameters, self.OUTPUT, context)
        with open(out, "w") as f:
            json.dump(report, f, indent=2)
        feedback.pushInfo(json.dumps(report, indent=2)[:4000])
        result = {self.OUTPUT: out}
        for name, (section, key) in self.FIGURES.items():
            value = report.get(section, {}).get(key) if isinstance(report.get(section), dict) else None
            if isinstance(value, (int, float)):
                result[name] = value
        if png:
            result[self.PNG] = png
        result[self.LAYERS] = []
        if vertices:
            result[self.VERTICES] = vertices
            if vertices.lower().endswith(".gpkg"):
                result[self.LAYERS] = self.load_gpkg_layers(vertices, ["vertices"], context, self.VERTICES)
        return result
