"""The roofsweep Processing provider (algorithm ids roofsweep:<name>)."""

from qgis.core import QgsProcessingProvider
from qgis.PyQt.QtGui import QIcon

from . import runner
from .algorithms import ALGORITHMS


class RoofsweepProvider(QgsProcessingProvider):
    def id(self):
        return "roofsweep"

    def name(self):
        return "roofsweep"

    def longName(self):
        return "roofsweep (LoD2 buildings from oriented aerial images)"

    def icon(self):
        return QIcon()

    def load(self):
        self._register_setting()
        self.refreshAlgorithms()
        return True

    def unload(self):
        try:
            from processing.core.ProcessingConfig import ProcessingConfig

            ProcessingConfig.removeSetting(runner.EXE_SETTING)
        except (ImportError, KeyError):
            pass

    def _register_setting(self):
        # The Processing plugin is absent only in bare scripts; the program
        # is then found through ROOFSWEEP_EXE, PATH or the build tree.
        try:
            from processing.core.ProcessingConfig import ProcessingConfig, Setting
        except ImportError:
            return
        ProcessingConfig.settingIcons[self.name()] = self.icon()
        ProcessingConfig.addSetting(Setting(self.name(), runner.EXE_SETTING, "roofsweep executable", "",
                                            valuetype=Setting.FILE))
        ProcessingConfig.readSettings()

    def loadAlgorithms(self):
        for cls in ALGORITHMS:
            self.addAlgorithm(cls())
