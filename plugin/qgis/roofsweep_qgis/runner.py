"""Finds and runs the roofsweep program for the Processing algorithms.

The provider never computes anything itself: every algorithm is one call of
the GDAL-style program, so QGIS and the command line give identical results.
"""

import codecs
import glob
import os
import re
import shutil
import subprocess
import threading
import time
from queue import Empty, Queue

from qgis.core import QgsProcessingException

EXE_SETTING = "ROOFSWEEP_EXE"
EXE_ENV = "ROOFSWEEP_EXE"

# Build folders tried when the plugin runs from a source checkout
# (plugin/qgis/roofsweep_qgis -> repository root is three levels up).
_BUILD_GLOBS = ("build", "build-*")


def _is_executable(path):
    return bool(path) and os.path.isfile(path) and os.access(path, os.X_OK)


def _setting_value():
    # ProcessingConfig lives in the Processing plugin; it is missing only in
    # bare scripts that did not initialise Processing.
    try:
        from processing.core.ProcessingConfig import ProcessingConfig
    except ImportError:
        return None
    try:
        return ProcessingConfig.getSetting(EXE_SETTING)
    except Exception:  # the setting is not registered (provider not loaded)
        return None


def _build_tree_candidates():
    root = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))
    found = []
    for pattern in _BUILD_GLOBS:
        for d in glob.glob(os.path.join(root, pattern)):
            exe = os.path.join(d, "plugin", "cli", "roofsweep")
            if _is_executable(exe):
                found.append(exe)
    # The plain "build" folder (what `make` uses) first, then the newest.
    found.sort(key=lambda p: (os.path.basename(os.path.dirname(os.path.dirname(os.path.dirname(p)))) != "build",
                              -os.path.getmtime(p)))
    return found


def find_executable():
    """The roofsweep program: provider setting, ROOFSWEEP_EXE, PATH, build tree.

    Raises QgsProcessingException naming every place looked at when none has it.
    """
    tried = []
    value = _setting_value()
    if value:
        if _is_executable(value):
            return value
        tried.append("provider setting {} = '{}' (not an executable file)".format(EXE_SETTING, value))
    value = os.environ.get(EXE_ENV)
    if value:
        if _is_executable(value):
            return value
        tried.append("environment {} = '{}' (not an executable file)".format(EXE_ENV, value))
    on_path = shutil.which("roofsweep")
    if on_path:
        return on_path
    tried.append("'roofsweep' on PATH")
    builds = _build_tree_candidates()
    if builds:
        return builds[0]
    tried.append("build folders of the source checkout")
    raise QgsProcessingException(
        "roofsweep program not found; looked at: " + "; ".join(tried) +
        ". Set it in Processing > Options > Providers > roofsweep or in ROOFSWEEP_EXE.")


_help_cache = {}


def command_help(exe, command):
    """(available, help text) of `roofsweep COMMAND --help`; cached per program build."""
    try:
        key = (exe, os.path.getmtime(exe), command)
    except OSError:
        key = (exe, None, command)
    if key not in _help_cache:
        try:
            p = subprocess.run([exe, command, "--help"], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                               stdin=subprocess.DEVNULL, timeout=60, universal_newlines=True)
        except (OSError, subprocess.TimeoutExpired) as e:
            raise QgsProcessingException("cannot run {}: {}".format(exe, e))
        _help_cache[key] = (p.returncode == 0, p.stdout)
    return _help_cache[key]


def require_command(exe, command, options=()):
    """Raises unless this build of the program has COMMAND and every option in OPTIONS.

    Checking the usage first turns a version mismatch between plugin and
    program into one clear message instead of a usage dump half-way.
    """
    ok, text = command_help(exe, command)
    if not ok:
        raise QgsProcessingException("roofsweep {} is not available in this build ({})".format(command, exe))
    known = set(re.findall(r"(?<![\w-])(--?[A-Za-z_][\w-]*)", text))
    missing = [o for o in options if o not in known]
    if missing:
        raise QgsProcessingException(
            "roofsweep {} in this build ({}) does not accept {}; the plugin and the program "
            "are from different versions".format(command, exe, ", ".join(missing)))


class ProgressParser:
    """Turns GDALTermProgress output (`0...10...20...100 - done.`) into percentages.

    GDAL prints a number every 10 % and a dot every 2.5 % in between, with no
    newline until the end, so the stream is parsed character by character.
    Other stdout text is returned line by line.
    """

    _DONE = " - done."

    def __init__(self):
        self._line = ""
        self._line_best = -1.0
        self.last = None

    def _progress_of(self, text):
        # A progress line starts with "0" and holds only digits and dots,
        # then possibly (part of) " - done.". Scanned by hand: a regular
        # expression for this grammar backtracks exponentially.
        if not text or text[0] != "0":
            return None
        head, sep, tail = text.partition(" ")
        if sep and not self._DONE.startswith(sep + tail):
            return None
        if head.strip("0123456789."):
            return None
        stripped = head.rstrip(".")
        dots = len(head) - len(stripped)
        digits = len(stripped) - len(stripped.rstrip("0123456789"))
        if digits == 0 or dots > 3:
            return None
        return min(float(stripped[-digits:]) + 2.5 * dots, 100.0)

    def feed(self, text):
        """Returns (progress or None, [complete non-progress lines])."""
        lines = []
        progress = None
        for ch in text:
            if ch in "\r\n":
                if self._line and self._progress_of(self._line) is None:
                    lines.append(self._line)
                self._line = ""
                self._line_best = -1.0
                continue
            self._line += ch
            p = self._progress_of(self._line)
            # Monotonic within a line: a number cut in two by a pipe read
            # ("1" of "10") must not move the bar back.
            if p is not None and p >= self._line_best:
                self._line_best = p
                progress = p
        if progress is not None:
            self.last = progress
        return progress, lines

    def flush(self):
        rest = self._line
        self._line = ""
        if rest and self._progress_of(rest) is None:
            return [rest]
        return []


def _pump(stream, queue, tag, chunked):
    try:
        if chunked:
            # Progress has no newline until the end: read what is there, and
            # decode incrementally so a UTF-8 character split by a read survives.
            fd = stream.fileno()
            decoder = codecs.getincrementaldecoder("utf-8")("replace")
            while True:
                data = os.read(fd, 4096)
                if not data:
                    break
                queue.put((tag, decoder.decode(data)))
        else:
            for line in iter(stream.readline, b""):
                queue.put((tag, line.decode("utf-8", "replace").rstrip("\r\n")))
    finally:
        queue.put((tag, None))


_ERROR_LINE = re.compile(r"^(ERROR \d+|FAILURE): ")
_WARNING_LINE = re.compile(r"^Warning \d+: ")


def run(exe, args, feedback, capture_stdout=False, cwd=None):
    """Runs `exe args`, streaming progress and messages into FEEDBACK.

    Returns the stdout text when CAPTURE_STDOUT (progress is still parsed
    out of it). Raises QgsProcessingException on cancel or non-zero exit.
    """
    cmd = [exe] + [str(a) for a in args]
    if feedback is not None:
        feedback.pushCommandInfo(" ".join(_quote(a) for a in cmd))
    try:
        proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, stdin=subprocess.DEVNULL,
                                cwd=cwd)
    except OSError as e:
        raise QgsProcessingException("cannot start {}: {}".format(exe, e))

    queue = Queue()
    threads = [threading.Thread(target=_pump, args=(proc.stdout, queue, "out", True), daemon=True),
               threading.Thread(target=_pump, args=(proc.stderr, queue, "err", False), daemon=True)]
    for t in threads:
        t.start()

    parser = ProgressParser()
    captured = []
    errors = []
    open_streams = 2
    cancelled = False
    while open_streams:
        if feedback is not None and feedback.isCanceled() and not cancelled:
            cancelled = True
            _stop(proc)
        try:
            tag, data = queue.get(timeout=0.1)
        except Empty:
            continue
        if data is None:
            open_streams -= 1
            continue
        if tag == "out":
            progress, lines = parser.feed(data)
            if capture_stdout:
                captured.append(data)
            if feedback is not None:
                if progress is not None:
                    feedback.setProgress(progress)
                if not capture_stdout:
                    for line in lines:
                        feedback.pushConsoleInfo(line)
        else:
            if _ERROR_LINE.match(data):
                errors.append(data)
            if feedback is not None:
                if _ERROR_LINE.match(data):
                    feedback.reportError(data, False)
                elif _WARNING_LINE.match(data):
                    feedback.pushWarning(data)
                elif data.strip():
                    feedback.pushInfo(data)
    rc = proc.wait()
    for t in threads:
        t.join(timeout=5)
    if feedback is not None and not capture_stdout:
        for line in parser.flush():
            feedback.pushConsoleInfo(line)

    if cancelled or (feedback is not None and feedback.isCanceled()):
        raise QgsProcessingException("roofsweep {} was cancelled".format(args[0] if args else ""))
    if rc != 0:
        detail = errors[-1] if errors else "exit code {}".format(rc)
        raise QgsProcessingException("roofsweep {} failed: {}".format(args[0] if args else "", detail))
    if capture_stdout:
        return _strip_progress("".join(captured))
    return None


def _strip_progress(text):
    """Drops GDAL progress lines from captured stdout (JSON or tables follow them)."""
    probe = ProgressParser()
    return "".join(line for line in text.splitlines(True)
                   if not (line.rstrip().endswith("done.") and probe._progress_of(line.rstrip("\r\n")) is not None))


def _stop(proc, grace_seconds=5.0):
    """Terminates the program, then kills it if it ignores SIGTERM."""
    if proc.poll() is not None:
        return
    proc.terminate()
    deadline = time.monotonic() + grace_seconds
    while proc.poll() is None and time.monotonic() < deadline:
        time.sleep(0.05)
    if proc.poll() is None:
        proc.kill()


def _quote(a):
    return a if re.match(r"^[\w@%+=:,./-]+$", a) else "'" + a.replace("'", "'\\''") + "'"
