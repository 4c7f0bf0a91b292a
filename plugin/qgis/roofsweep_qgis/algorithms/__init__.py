"""The roofsweep Processing algorithms, one per program subcommand."""

from .convert import ConvertAlgorithm
from .evaluate import EvaluateAlgorithm
from .import_block import ImportAlgorithm
from .info import InfoAlgorithm
from .lines import LinesAlgorithm
from .match import MatchAlgorithm
from .overlay import OverlayAlgorithm
from .reconstruct import ReconstructAlgorithm
from .simulate import SimulateAlgorithm

ALGORITHMS = (ImportAlgorithm, InfoAlgorithm, LinesAlgorithm, MatchAlgorithm, ReconstructAlgorithm,
              EvaluateAlgorithm, OverlayAlgorithm, SimulateAlgorithm, ConvertAlgorithm)
