"""medial batch: one `medial` command over many inputs, on this machine or a Dask cluster.

    medial batch COMMAND INPUT... --out-dir DIR [COMMAND OPTIONS...]
                 [--scheduler tcp://HOST:PORT | --workers N] [--timeout SECONDS] [--retries K] [--resume]
                 [--output-name PATTERN] [--quiet]

Every input runs in a child process of its own (the `medial` command), on a Dask worker: a crash loses that
input only. DIR/manifest.csv gets one row per input as soon as it finishes. From Python:

    import medial.batch
    rows = medial.batch.run("skeleton", ["meshes/*.off"], "out", options=["--nodes", "25"], workers=2)
"""
import csv
import glob
import io
import json
import os
import shutil
import signal
import socket
import subprocess
import sys
import time
from dataclasses import dataclass, field, fields
from typing import Optional

COMMANDS = {"skeleton": ".vtp", "sqm": ".vtp", "centerline": ".vtp", "sketch": ".vtp", "render": ".png"}


@dataclass
class Row:
    """One input's line of the manifest, typed alike whether it ran now or was read back (--resume).
    `row["status"]` still works as on the dictionaries of earlier releases."""
    input: str
    output: str
    status: str                       # ok | error | crash | timeout
    exit_code: Optional[int] = None   # None: killed on time-out, or lost on the cluster
    seconds: Optional[float] = None
    worker: str = ""
    message: str = ""                 # the command's last line on stderr
    timings: dict = field(default_factory=dict)  # the command's --timings (stage: seconds)

    def __getitem__(self, name):
        return getattr(self, name)

    def csv_values(self):
        return [self.input, self.output, self.status, "" if self.exit_code is None else str(self.exit_code),
                "" if self.seconds is None else "%.3f" % self.seconds, self.worker, self.message,
                json.dumps(self.timings, separators=(",", ":")) if self.timings else ""]

    @classmethod
    def from_csv(cls, values):
        """A row of manifest.csv (a csv.DictReader dictionary) as a Row."""
        def number(text, kind):
            try:
                return kind(text) if text not in (None, "") else None
            except ValueError:
                return None
        try:
            timings = json.loads(values.get("timings") or "{}")
        except ValueError:
            timings = {}
        return cls(values.get("input", ""), values.get("output", ""), values.get("status", ""),
                   number(values.get("exit_code"), int), number(values.get("seconds"), float),
                   values.get("worker", ""), values.get("message", ""), timings)


FIELDS = [f.name for f in fields(Row)]
USAGE = """usage: medial batch COMMAND INPUT... --out-dir DIR [COMMAND OPTIONS...]
                    [--scheduler tcp://HOST:PORT | --workers N] [--timeout SECONDS] [--retries K] [--resume]
                    [--output-name PATTERN] [--quiet]"""
HELP = USAGE + """

Runs `medial COMMAND` (skeleton, sqm, centerline, sketch, render) on every INPUT, in parallel on Dask
workers: by default a local cluster of one single-threaded worker per core, or the running cluster at
--scheduler. Each input runs in its own child process. DIR/manifest.csv gets one row per input as soon as it
finishes: input, output, status (ok|error|crash|timeout), exit_code, seconds, worker, message, timings.
  INPUT                    files, folders (a folder of DICOM files is one input), glob patterns, @LIST.txt
  --out-dir DIR            where outputs and manifest.csv go
  --output-name PATTERN    output file name in DIR (default {stem}.vtp, {stem}.png for render); {stem},
                           {name} and {parent} expand, in COMMAND OPTIONS too (e.g. --rig {stem}.glb)
  --scheduler ADDRESS      a running Dask scheduler (tcp://HOST:PORT); its workers need Medial installed
                           and the files on a shared path
  --workers N              workers of the local cluster (default: one per core)
  --timeout SECONDS        kill an input's process past this time (status timeout)
  --retries K              run crashed and timed-out inputs again, up to K times (clean errors are not)
  --resume                 skip inputs whose manifest row says ok and whose output exists
  --quiet                  no progress line
Other options are passed to `medial COMMAND` unchanged. Exit status: 0 all ok, 1 any failed, 2 usage."""


class UsageError(Exception):
    pass


# -- inputs and outputs ------------------------------------------------------------------------------------

def _is_dicom_folder(path):
    names = os.listdir(path)
    return any(n.lower().endswith(".dcm") for n in names) or (
        names and all(os.path.isfile(os.path.join(path, n)) and "." not in n for n in names))


def expand_inputs(items):
    """Files, folders (a DICOM series folder is one input, another folder gives its files), glob patterns
    and @LIST.txt (one path per line) -> the inputs, in order, each once. A path that does not exist is
    kept: its run reports it."""
    inputs = []
    for item in items:
        if item.startswith("@"):
            with open(item[1:]) as listing:
                inputs += expand_inputs([line.strip() for line in listing if line.strip() and not line.startswith("#")])
        elif any(c in item for c in "*?["):
            inputs += sorted(glob.glob(item))
        elif os.path.isdir(item) and not _is_dicom_folder(item):
            inputs += sorted(os.path.join(item, n) for n in os.listdir(item) if os.path.isfile(os.path.join(item, n)))
        else:
            inputs.append(item)
    seen = set()
    return [i for i in inputs if not (i in seen or seen.add(i))]


def _size_of(path):
    """Bytes of a file, or of the files of a folder (a DICOM series); 0 for what does not exist."""
    try:
        if os.path.isdir(path):
            return sum(os.path.getsize(os.path.join(path, n)) for n in os.listdir(path))
        return os.path.getsize(path)
    except OSError:
        return 0


def names_of(path):
    name = os.path.basename(os.path.normpath(path))
    stem = name
    for ext in (".nii.gz", ".inr.gz", ".vtk.gz"):
        if stem.lower().endswith(ext):
            stem = stem[: -len(ext)]
            break
    else:
        stem = os.path.splitext(name)[0] if "." in name[1:] else name
    return {"stem": stem, "name": name, "parent": os.path.basename(os.path.dirname(os.path.abspath(path)))}


def expand(text, path):
    return text.format(**names_of(path)) if "{" in text else text


# -- one input ---------------------------------------------------------------------------------------------

def _worker_name():
    try:
        from distributed import get_worker
        return get_worker().address
    except Exception:
        return "%s:%d" % (socket.gethostname(), os.getpid())


# A worker is one core: the child's numeric libraries (OpenBLAS under CHOLMOD, OpenMP, VTK's SMP tools)
# stay on one thread too, unless the caller set them; two children each spawning a thread per core would
# fight over the cores and lose the speed-up of a second worker.
SINGLE_THREADED = {"OMP_NUM_THREADS": "1", "OPENBLAS_NUM_THREADS": "1", "MKL_NUM_THREADS": "1",
                   "VTK_SMP_MAX_THREADS": "1"}


def _child_environment():
    return dict(SINGLE_THREADED, **os.environ)


def run_one(medial, command, path, output, options, timeout=None, retries=0):
    """Runs `medial COMMAND PATH -o OUTPUT OPTIONS --quiet --timings` in a child process (retrying crashes
    and time-outs); returns the manifest row."""
    if not os.path.exists(medial) and shutil.which("medial"):
        medial = shutil.which("medial")  # a worker with Medial installed elsewhere
    arguments = [medial, command, path, "-o", output] + [expand(o, path) for o in options] + ["--quiet", "--timings"]
    for attempt in range(retries + 1):
        start = time.monotonic()
        try:
            done = subprocess.run(arguments, capture_output=True, text=True, timeout=timeout,
                                  start_new_session=True, env=_child_environment())
            code, out, err = done.returncode, done.stdout, done.stderr
            status = "ok" if code == 0 else "crash" if code < 0 else "error"
        except subprocess.TimeoutExpired as expired:
            code, status = None, "timeout"
            out, err = "", "killed after %g s" % timeout
        seconds = time.monotonic() - start
        if status not in ("crash", "timeout"):
            break
    lines = [line for line in (err or "").splitlines() if line.strip() and ": note: " not in line]
    message = lines[-1] if lines else ""
    if status == "crash":
        message = "killed by signal %d (%s)%s" % (-code, signal.Signals(-code).name, (": " + message) if message else "")
    timings = {}
    for line in (out or "").splitlines():
        if line.startswith("{"):
            try:
                timings = json.loads(line)
            except ValueError:
                pass
    return Row(path, output, status, code, seconds, _worker_name(), message, timings)


# -- the manifest ------------------------------------------------------------------------------------------

class Manifest:
    """DIR/manifest.csv: the header, then one row per finished input, each appended in a single write, so
    the file stays valid CSV whenever the driver stops."""

    def __init__(self, path):
        self.path = path
        self.rows = {}
        if os.path.exists(path):
            with open(path, newline="") as f:
                text = f.read()
            complete = text[: text.rfind("\n") + 1]  # a line cut by a crash is dropped
            for values in csv.DictReader(io.StringIO(complete)):
                row = Row.from_csv(values)
                self.rows[row.input] = row
        self._rewrite()

    def _line(self, row):
        out = io.StringIO()
        csv.writer(out, lineterminator="\n").writerow(row.csv_values())
        return out.getvalue()

    def _rewrite(self):
        temporary = self.path + ".tmp-%d" % os.getpid()
        with open(temporary, "w", newline="") as f:
            f.write(",".join(FIELDS) + "\n")
            for row in self.rows.values():
                f.write(self._line(row))
        os.replace(temporary, self.path)

    def add(self, row):
        if row.input in self.rows:  # a retried input: its new row replaces the old one
            self.rows[row.input] = row
            self._rewrite()
            return
        self.rows[row.input] = row
        descriptor = os.open(self.path, os.O_WRONLY | os.O_APPEND)
        try:
            os.write(descriptor, self._line(row).encode())
        finally:
            os.close(descriptor)


# -- the run -----------------------------------------------------------------------------------------------

def _medial_executable():
    return os.environ.get("MEDIAL_EXECUTABLE") or shutil.which("medial") or "medial"


class _Progress:
    def __init__(self, total, quiet):
        self.total, self.done, self.failed = total, 0, 0
        self.start = time.monotonic()
        self.shown = not quiet and sys.stderr.isatty()

    def step(self, row):
        self.done += 1
        self.failed += row.status != "ok"
        if not self.shown:
            return
        elapsed = time.monotonic() - self.start
        rate = self.done / elapsed if elapsed > 0 else 0
        left = (self.total - self.done) / rate if rate > 0 else 0
        width = 30
        filled = int(width * self.done / max(1, self.total))
        sys.stderr.write("\r[%s%s] %d/%d  ok %d  failed %d  %.1f files/s  %ds left " % (
            "#" * filled, "." * (width - filled), self.done, self.total, self.done - self.failed, self.failed,
            rate, left))
        sys.stderr.flush()

    def finish(self):
        if self.shown:
            sys.stderr.write("\n")


def run(command, inputs, out_dir, options=(), scheduler=None, workers=None, timeout=None, retries=0,
        resume=False, output_name=None, quiet=True, medial=None):
    """Runs `medial COMMAND` on every input (files, folders, globs, @lists) and returns the manifest rows,
    in the inputs' order, as Row objects. See the module's documentation for the options."""
    if command not in COMMANDS:
        raise UsageError("COMMAND is one of %s, not %r" % (", ".join(COMMANDS), command))
    paths = [os.path.abspath(p) for p in expand_inputs(list(inputs))]  # workers may run elsewhere
    out_dir = os.path.abspath(out_dir)
    if not paths:
        raise UsageError("no INPUT matches")
    os.makedirs(out_dir, exist_ok=True)
    pattern = output_name or "{stem}" + COMMANDS[command]
    manifest = Manifest(os.path.join(out_dir, "manifest.csv"))
    medial = medial or _medial_executable()
    options = [o if "{" not in o or os.path.isabs(o) or o.startswith("-") else os.path.join(out_dir, o)
               for o in options]
    todo = []
    for path in paths:
        output = os.path.join(out_dir, expand(pattern, path))
        old = manifest.rows.get(path)
        if resume and old and old.status == "ok" and os.path.exists(output):
            continue
        todo.append((path, output))
    todo.sort(key=lambda task: -_size_of(task[0]))
    progress = _Progress(len(todo), quiet)
    if todo:
        from distributed import Client, LocalCluster, as_completed
        cluster = None
        if scheduler:
            client = Client(scheduler)
        else:
            # The workers are threads of this process: each task's work is a child process anyway (which is
            # what isolates crashes), so worker processes would only add their start-up (0.5 s each here).
            cluster = LocalCluster(n_workers=workers or os.cpu_count() or 1, threads_per_worker=1,
                                   processes=False, dashboard_address=None)
            client = Client(cluster)
        try:
            # The largest inputs go first (Dask runs tasks in the order they are submitted): a long one
            # started last would leave the other workers idle at the end.
            futures = {client.submit(run_one, medial, command, path, output, options, timeout, retries,
                                     key="medial-%s-%d-%s" % (command, i, os.path.basename(path)), pure=False):
                       (path, output) for i, (path, output) in enumerate(todo)}
            for future in as_completed(futures):
                row = _row_of(future, *futures[future])
                manifest.add(row)
                progress.step(row)
        finally:
            progress.finish()
            client.close()
            if cluster:
                cluster.close()
    return [manifest.rows[p] for p in paths if p in manifest.rows]


def _row_of(future, path, output):
    """The task's manifest row; a task Dask itself gave up on (its workers kept dying while running it:
    KilledWorker) or that raised is a crash of that input, not of the batch."""
    try:
        return future.result()
    except Exception as e:
        return Row(path, output, "crash", message="the task failed on the cluster: %s: %s" % (type(e).__name__, e))


def _parse(argv):
    if not argv or argv[0] in ("-h", "--help"):
        print(HELP)
        sys.exit(0)
    command, rest = argv[0], argv[1:]
    if command not in COMMANDS:
        raise UsageError("COMMAND is one of %s, not %r" % (", ".join(COMMANDS), command))
    ours = {"--out-dir": 1, "--scheduler": 1, "--workers": 1, "--timeout": 1, "--retries": 1, "--resume": 0,
            "--output-name": 1, "--quiet": 0, "--help": 0, "-h": 0}
    values, inputs, passed = {}, [], []
    i = 0
    while i < len(rest):
        arg = rest[i]
        name, _, inline = arg.partition("=")
        if name in ours:
            if name in ("--help", "-h"):
                print(HELP)
                sys.exit(0)
            if ours[name]:
                if inline:
                    values[name] = inline
                elif i + 1 < len(rest):
                    i += 1
                    values[name] = rest[i]
                else:
                    raise UsageError("option %s needs a value" % name)
            else:
                values[name] = True
        elif arg.startswith("-") and len(arg) > 1:
            passed.append(arg)  # the command's own option, and its value if it takes one
            if not inline and i + 1 < len(rest) and name in _options_with_value(command):
                i += 1
                passed.append(rest[i])
        else:
            inputs.append(arg)
        i += 1
    if "--out-dir" not in values:
        raise UsageError("batch needs --out-dir DIR")
    if "--scheduler" in values and "--workers" in values:
        raise UsageError("give --scheduler or --workers, not both")
    numbers = {}
    for name, kind in (("--workers", int), ("--timeout", float), ("--retries", int)):
        if name in values:
            try:
                numbers[name] = kind(values[name])
            except ValueError:
                raise UsageError("%s expects a number, got %r" % (name, values[name]))
            if numbers[name] < (1 if name == "--workers" else 0):
                raise UsageError("%s must be %s" % (name, ">= 1" if name == "--workers" else ">= 0"))
    return command, inputs, passed, values, numbers


def _options_with_value(command):
    """The options of `medial COMMAND` that take a value, from the command's own option table (the one
    its parsing uses: `medial COMMAND --list-options`)."""
    if command not in _options_with_value.known:
        text = subprocess.run([_medial_executable(), command, "--list-options"], capture_output=True,
                              text=True).stdout
        values = [line.split()[1:] for line in text.splitlines() if line.startswith("values")]
        if not values:
            raise UsageError("cannot read the options of 'medial %s' (is %s Medial's command?)"
                             % (command, _medial_executable()))
        _options_with_value.known[command] = set(values[0])
    return _options_with_value.known[command]


_options_with_value.known = {}


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    try:
        command, inputs, passed, values, numbers = _parse(argv)
        rows = run(command, inputs, values["--out-dir"], passed, scheduler=values.get("--scheduler"),
                   workers=numbers.get("--workers"), timeout=numbers.get("--timeout"),
                   retries=numbers.get("--retries", 0), resume=bool(values.get("--resume")),
                   output_name=values.get("--output-name"), quiet=bool(values.get("--quiet")))
    except UsageError as e:
        sys.stderr.write("medial batch: %s (see 'medial batch --help')\n" % e)
        return 2
    counts = {}
    for row in rows:
        counts[row.status] = counts.get(row.status, 0) + 1
    failed = len(rows) - counts.get("ok", 0)
    print("medial batch: %d inputs: %s; manifest %s" % (
        len(rows), ", ".join("%d %s" % (n, s) for s, n in sorted(counts.items())) or "none run",
        os.path.join(values["--out-dir"], "manifest.csv")))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
