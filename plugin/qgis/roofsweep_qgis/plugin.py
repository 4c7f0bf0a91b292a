"""QGIS plugin entry: registers the roofsweep Processing provider."""

from qgis.core import QgsApplication

from .provider import RoofsweepProvider


class RoofsweepPlugin:
    def __init__(self, iface):
        # iface is None under qgis_process; nothing here may rely on it.
        self.iface = iface
        self.provider = None

    def initProcessing(self):
        if self.provider is None:
            self.provider = RoofsweepProvider()
            QgsApplication.processingRegistry().addProvider(self.provider)

    def initGui(self):
        self.initProcessing()

    def unload(self):
        if self.provider is not None:
            QgsApplication.processingRegistry().removeProvider(self.provider)
            self.provider = None
