"""Runs the `medial` command in a temporary folder, reading its progress lines (MEDIAL_PROGRESS=lines) on a
thread, so that an operator can show progress and cancel it (SIGINT: the command exits with 130)."""
import os
import shutil
import signal
import subprocess
import tempfile
import threading


class MedialError(Exception):
    """The command failed, was not found or was cancelled; str() is the message for the user."""


def find_medial(preferred=""):
    """The `medial` executable: `preferred` (the add-on's preference) when set, else the one on PATH."""
    if preferred:
        path = os.path.abspath(os.path.expanduser(preferred))
        if os.path.isfile(path) and os.access(path, os.X_OK):
            return path
        raise MedialError("medial not found at %s (the Medial add-on's preferences)" % preferred)
    found = shutil.which("medial")
    if not found:
        raise MedialError("medial not found on PATH: install Medial, or set its path in the add-on's preferences")
    return found


class Job:
    """One run of `medial ARGS`, its progress read as lines from stderr, in its own temporary folder."""

    def __init__(self, executable):
        self.executable = executable
        self.folder = tempfile.mkdtemp(prefix="medial-blender-")
        self.process = None
        self.progress = 0.0  # 0..1 of the current stage
        self.stage = ""
        self.messages = []  # stderr lines that are not progress
        self.cancelled = False
        self._reader = None

    def path(self, name):
        return os.path.join(self.folder, name)

    def start(self, args):
        env = dict(os.environ, MEDIAL_PROGRESS="lines")
        try:
            self.process = subprocess.Popen([self.executable] + [str(a) for a in args], stdout=subprocess.DEVNULL,
                                            stderr=subprocess.PIPE, text=True, env=env, cwd=self.folder)
        except OSError as error:
            raise MedialError("cannot run %s: %s" % (self.executable, error.strerror))
        self._reader = threading.Thread(target=self._read_stderr, daemon=True)
        self._reader.start()

    def _read_stderr(self):
        for line in self.process.stderr:
            line = line.rstrip("\n")
            if line.startswith("medial-progress "):
                label, _, percent = line[len("medial-progress "):].rpartition(" ")
                self.stage, self.progress = label, int(percent) / 100.0
            elif line.strip():
                self.messages.append(line)

    def running(self):
        return self.process is not None and self.process.poll() is None

    def cancel(self):
        self.cancelled = True
        if self.running():
            self.process.send_signal(signal.SIGINT)
            try:
                self.process.wait(timeout=10)
            except subprocess.TimeoutExpired:
                self.process.kill()
                self.process.wait()

    def finish(self):
        """Waits for the command; raises MedialError with its message when it failed or was cancelled."""
        code = self.process.wait()
        self._reader.join()
        if self.cancelled or code == 130:
            raise MedialError("cancelled")
        if code != 0:
            errors = [m for m in self.messages if "note:" not in m] or self.messages
            raise MedialError(errors[-1] if errors else "medial failed with exit status %d" % code)

    def notes(self):
        return [m for m in self.messages if "note:" in m]

    def run(self, args):
        """start() and finish(): for scripts and background Blender, where no modal operator runs."""
        self.start(args)
        self.finish()

    def cleanup(self):
        if self.running():
            self.cancel()
        shutil.rmtree(self.folder, ignore_errors=True)
