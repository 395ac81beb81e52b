"""MedialError, and running a VTK algorithm so that its complaints become that exception.

VTK reports a failed update by printing to its output window (ANSI-coloured on a terminal, with
`vtkInformation` dumps from the executive) and leaving the output empty; nothing raises. `run` watches
the algorithm's ErrorEvent and WarningEvent, sends everything else VTK prints meanwhile into a string
instead of stderr, and raises MedialError with the algorithm's own one-line message.
"""
import re
import warnings

from vtkmodules.vtkCommonCore import VTK_STRING, vtkCommand, vtkLogger, vtkOutputWindow, vtkStringOutputWindow
from vtkmodules.util.misc import calldata_type


class MedialError(RuntimeError):
    """Bad input or a failed algorithm: the filter's one-line message (missing file, open mesh, no radius,
    empty selection ...)."""


class MedialWarning(UserWarning):
    """Something a user should know about a result that is still valid (fewer nodes than asked, parts of a
    volume left out ...)."""


# VTK's prefix: "ERROR: In /path/file.cxx, line 12\nvtkClass (0x55d...): " (or "Warning: In ...").
_VTK_PREFIX = re.compile(r"^\s*(ERROR|Warning|Generic Warning): In [^\n]*, line \d+\n(\w+ \([^)]*\): )?", re.S)


def strip_vtk_prefix(message):
    """`message` without VTK's file, line and object prefix, on one line."""
    return " ".join(_VTK_PREFIX.sub("", message).split())


class _Messages:
    """ErrorEvent and WarningEvent observers on some VTK objects, and what they received."""

    def __init__(self):
        self.errors, self.warnings, self._observed = [], [], []

    def watch(self, vtk_object):
        @calldata_type(VTK_STRING)
        def on_error(caller, event, message):
            self.errors.append(strip_vtk_prefix(message or ""))

        @calldata_type(VTK_STRING)
        def on_warning(caller, event, message):
            self.warnings.append(strip_vtk_prefix(message or ""))

        tags = (vtk_object.AddObserver(vtkCommand.ErrorEvent, on_error),
                vtk_object.AddObserver(vtkCommand.WarningEvent, on_warning))
        self._observed.append((vtk_object, tags))

    def release(self):
        for vtk_object, tags in self._observed:
            for tag in tags:
                vtk_object.RemoveObserver(tag)
        self._observed = []


class quiet_vtk:
    """Within the block, VTK prints nothing: its output window writes into a string (`text`) and its logger
    stays off stderr. The previous window and verbosity come back on exit."""

    def __enter__(self):
        self._previous_window = vtkOutputWindow.GetInstance()
        self._window = vtkStringOutputWindow()
        vtkOutputWindow.SetInstance(self._window)
        self._previous_verbosity = vtkLogger.GetCurrentVerbosityCutoff()
        vtkLogger.SetStderrVerbosity(vtkLogger.VERBOSITY_OFF)
        return self

    def __exit__(self, *exception):
        vtkOutputWindow.SetInstance(self._previous_window)
        vtkLogger.SetStderrVerbosity(self._previous_verbosity)
        return False

    @property
    def text(self):
        return self._window.GetOutput()


def run(algorithm, what, *, write=False):
    """Updates `algorithm` (or calls its Write() when `write`) with VTK kept quiet. Raises MedialError
    "`what`: <the algorithm's message>" when it reports an error or fails; its warnings become
    MedialWarning, and are returned (a list of strings)."""
    messages = _Messages()
    messages.watch(algorithm)
    if algorithm.GetExecutive() is not None:
        messages.watch(algorithm.GetExecutive())
    try:
        with quiet_vtk() as quiet:
            succeeded = algorithm.Write() == 1 if write else algorithm.GetExecutive().Update() == 1
    finally:
        messages.release()
    errors = [m for m in messages.errors if m]
    if errors or not succeeded:
        # The algorithm's own message first; the executive's "returned failure for request" dumps add
        # nothing a user can act on.
        own = [m for m in errors if "returned failure for request" not in m]
        printed = [strip_vtk_prefix(block) for block in re.split(r"\n\s*\n", quiet.text) if "ERROR" in block]
        reason = (own or printed or errors or ["failed without a message"])[0]
        raise MedialError(reason if reason.startswith(what) else "%s: %s" % (what, reason))
    notes = [m for m in messages.warnings if m]
    for message in notes:
        warnings.warn("%s: %s" % (what, message), MedialWarning, stacklevel=3)
    return notes
