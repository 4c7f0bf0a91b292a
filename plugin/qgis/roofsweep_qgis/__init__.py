"""roofsweep QGIS plugin: a Processing provider that runs the roofsweep program."""


def classFactory(iface):
    from .plugin import RoofsweepPlugin

    return RoofsweepPlugin(iface)
