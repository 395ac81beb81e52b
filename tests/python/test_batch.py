"""medial batch: a local cluster, a real loopback cluster, isolation of crashes and time-outs, retries,
resume, and a manifest that stays valid when the driver is killed. Every scheduler and worker binds
127.0.0.1 and is stopped by pid."""
import csv
import json
import os
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import time
import unittest

MEDIAL = os.environ["MEDIAL_EXECUTABLE"]
SOURCE = os.environ.get("MEDIAL_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
SKELETONS = os.path.join(SOURCE, "data", "skeletons", "sqm")
TUBES = os.path.join(SOURCE, "data", "volumes", "tubes")

# A stand-in `medial` for isolation tests: it aborts on inputs named *abort*, sleeps on *sleep*, counts its
# runs of each input in COUNT_DIR, and otherwise writes its output.
STAND_IN = """#!/bin/sh
input=$2 output=$4
echo x >> "$COUNT_DIR/$(basename "$input").runs"
case "$input" in
  *abort*) kill -ABRT $$ ;;
  *sleep*) sleep 30 ;;
  *slow*) sleep 0.4 ;;
esac
echo made > "$output"
echo '{"total": 0.01}'
"""


def rows(out_dir):
    with open(os.path.join(out_dir, "manifest.csv"), newline="") as f:
        return {os.path.basename(r["input"]): r for r in csv.DictReader(f)}


def run_count(counts, name):
    """How many times the stand-in ran for input `name`."""
    with open(os.path.join(counts, name + ".runs")) as f:
        return len(f.read().split())


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def worker_processes_of(nanny):
    """The pids of the worker processes a dask-worker's nanny started (multiprocessing's spawn)."""
    children = []
    for task in os.listdir("/proc/%d/task" % nanny):  # any of its threads may have started it
        with open("/proc/%d/task/%s/children" % (nanny, task)) as f:
            children += [int(pid) for pid in f.read().split()]
    workers = []
    for pid in children:
        try:
            with open("/proc/%d/cmdline" % pid, "rb") as f:
                if b"spawn_main" in f.read():  # not multiprocessing's resource tracker
                    workers.append(pid)
        except FileNotFoundError:
            pass
    return workers


class LoopbackCluster:
    """dask-scheduler and two single-threaded dask-workers (each under its nanny) on 127.0.0.1, with this
    build's package on their path; stopped by pid on exit."""

    def __init__(self, env=None):
        self.env = dict(os.environ, PYTHONPATH=os.path.join(os.path.dirname(MEDIAL), "..", "lib", "python3",
                                                            "dist-packages"), **(env or {}))
        self.address = "tcp://127.0.0.1:%d" % free_port()
        self.processes = []

    def __enter__(self):
        port = self.address.rsplit(":", 1)[1]
        self.processes.append(subprocess.Popen(["/usr/bin/dask-scheduler", "--host", "127.0.0.1", "--port", port,
                                                "--no-dashboard"], stdout=subprocess.DEVNULL,
                                               stderr=subprocess.DEVNULL, env=self.env))
        time.sleep(2)
        for _ in range(2):
            self.processes.append(subprocess.Popen(
                ["/usr/bin/dask-worker", self.address, "--host", "127.0.0.1", "--nthreads", "1", "--no-dashboard"],
                stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=self.env))
        time.sleep(4)
        return self

    def __exit__(self, *_):
        for process in reversed(self.processes):
            process.send_signal(signal.SIGTERM)
        for process in reversed(self.processes):
            try:
                process.wait(timeout=10)
            except subprocess.TimeoutExpired:
                process.kill()
                process.wait()


class Batch(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.mkdtemp(prefix="medial-batch-test-")
        self.inputs = os.path.join(self.dir, "in")
        os.makedirs(self.inputs)

    def tearDown(self):
        shutil.rmtree(self.dir, ignore_errors=True)

    def batch(self, *args, medial=MEDIAL, env=None):
        environment = dict(os.environ, **(env or {}))
        return subprocess.run([medial, "batch"] + list(args), capture_output=True, text=True, env=environment,
                              timeout=600)

    def twenty_skeletons(self):
        names = sorted(n for n in os.listdir(SKELETONS) if n.endswith(".vtp"))
        for k in range(20):
            shutil.copy(os.path.join(SKELETONS, names[k % len(names)]), os.path.join(self.inputs, "s%02d.vtp" % k))
        with open(os.path.join(self.inputs, "corrupt.vtp"), "w") as f:
            f.write("not a skeleton\n")

    def stand_in(self):
        path = os.path.join(self.dir, "medial-stand-in")
        with open(path, "w") as f:
            f.write(STAND_IN)
        os.chmod(path, 0o755)
        counts = os.path.join(self.dir, "counts")
        os.makedirs(counts, exist_ok=True)
        return path, counts

    def test_local_cluster_gives_a_row_per_input(self):
        self.twenty_skeletons()
        out = os.path.join(self.dir, "out")
        r = self.batch("sqm", self.inputs, os.path.join(self.inputs, "missing.vtp"), "--out-dir", out, "--workers", "2")
        self.assertEqual(r.returncode, 1, r.stderr)
        table = rows(out)
        self.assertEqual(len(table), 22)
        ok = [row for row in table.values() if row["status"] == "ok"]
        self.assertEqual(len(ok), 20)
        for row in ok:
            self.assertGreater(os.path.getsize(row["output"]), 1000)
            self.assertIn('"sqm"', row["timings"])
        for name in ("corrupt.vtp", "missing.vtp"):
            self.assertEqual(table[name]["status"], "error")
            self.assertEqual(table[name]["exit_code"], "1")
            self.assertIn(name, table[name]["message"])
            self.assertNotIn("\n", table[name]["message"])
        self.assertIn("20 ok", r.stdout)

    def test_a_loopback_cluster_shares_the_inputs_between_its_workers(self):
        self.twenty_skeletons()
        os.remove(os.path.join(self.inputs, "corrupt.vtp"))
        with LoopbackCluster() as cluster:
            out = os.path.join(self.dir, "out")
            r = self.batch("sqm", self.inputs, "--out-dir", out, "--scheduler", cluster.address)
            self.assertEqual(r.returncode, 0, r.stderr)
            table = rows(out)
            self.assertEqual(len(table), 20)
            self.assertEqual({row["status"] for row in table.values()}, {"ok"})
            self.assertEqual(len({row["worker"] for row in table.values()}), 2, "both workers took inputs")

    def test_a_worker_that_dies_is_replaced_and_loses_no_input(self):
        stand_in, counts = self.stand_in()
        for k in range(12):
            open(os.path.join(self.inputs, "slow%02d.vtp" % k), "w").close()
        out = os.path.join(self.dir, "out")
        with LoopbackCluster(env={"COUNT_DIR": counts}) as cluster:
            driver = subprocess.Popen([MEDIAL, "batch", "sqm", self.inputs, "--out-dir", out, "--scheduler",
                                       cluster.address], env=dict(os.environ, MEDIAL_EXECUTABLE=stand_in),
                                      stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
            deadline = time.monotonic() + 120
            while time.monotonic() < deadline and len(os.listdir(counts)) < 3:
                time.sleep(0.05)
            nanny = cluster.processes[1]
            killed = worker_processes_of(nanny.pid)
            self.assertEqual(len(killed), 1, "dask-worker runs its worker in one child process")
            os.kill(killed[0], signal.SIGKILL)  # the worker dies, mid-task
            stdout, stderr = driver.communicate(timeout=300)
            self.assertEqual(driver.returncode, 0, stderr)
            table = rows(out)
            self.assertEqual(len(table), 12)
            self.assertEqual({row["status"] for row in table.values()}, {"ok"})
            deadline = time.monotonic() + 30
            replacement = worker_processes_of(nanny.pid)
            while time.monotonic() < deadline and len(replacement) != 1:
                time.sleep(0.2)
                replacement = worker_processes_of(nanny.pid)
            self.assertEqual(len(replacement), 1, "the nanny started a new worker")
            self.assertNotEqual(replacement, killed)

    def test_crashes_and_time_outs_lose_only_their_input_and_are_retried(self):
        stand_in, counts = self.stand_in()
        for name in ("a.vtp", "b.vtp", "abort.vtp", "sleep.vtp"):
            open(os.path.join(self.inputs, name), "w").close()
        out = os.path.join(self.dir, "out")
        env = {"MEDIAL_EXECUTABLE": stand_in, "COUNT_DIR": counts}
        r = self.batch("sqm", self.inputs, "--out-dir", out, "--workers", "2", "--timeout", "2", "--retries", "1",
                       env=env)
        self.assertEqual(r.returncode, 1, r.stderr)
        table = rows(out)
        self.assertEqual(table["a.vtp"]["status"], "ok")
        self.assertEqual(table["b.vtp"]["status"], "ok")
        self.assertEqual(table["abort.vtp"]["status"], "crash")
        self.assertIn("SIGABRT", table["abort.vtp"]["message"])
        self.assertEqual(table["sleep.vtp"]["status"], "timeout")
        runs = lambda name: run_count(counts, name)
        self.assertEqual(runs("abort.vtp"), 2, "--retries 1: a crash runs twice")
        self.assertEqual(runs("sleep.vtp"), 2)
        self.assertEqual(runs("a.vtp"), 1, "an ok input runs once")

    def test_resume_skips_what_is_done_and_reruns_what_failed(self):
        stand_in, counts = self.stand_in()
        for name in ["slow%d.vtp" % k for k in range(6)] + ["abort.vtp"]:
            open(os.path.join(self.inputs, name), "w").close()
        out = os.path.join(self.dir, "out")
        env = {"MEDIAL_EXECUTABLE": stand_in, "COUNT_DIR": counts}
        start = time.monotonic()
        first = self.batch("sqm", self.inputs, "--out-dir", out, "--workers", "1", env=env)
        first_seconds = time.monotonic() - start
        self.assertEqual(first.returncode, 1)
        start = time.monotonic()
        second = self.batch("sqm", self.inputs, "--out-dir", out, "--workers", "1", "--resume", env=env)
        self.assertEqual(second.returncode, 1)
        runs = lambda name: run_count(counts, name)
        self.assertEqual(runs("slow0.vtp"), 1, "an ok input is not run again")
        self.assertEqual(runs("abort.vtp"), 2, "a failed one is")
        self.assertEqual(len(rows(out)), 7)
        print("first run %.1f s, resumed %.1f s" % (first_seconds, time.monotonic() - start))

    def test_rows_are_typed_when_run_and_when_read_back(self):
        import medial.batch
        stand_in, counts = self.stand_in()
        for name in ("a.vtp", "abort.vtp"):
            open(os.path.join(self.inputs, name), "w").close()
        out = os.path.join(self.dir, "out")
        os.environ["COUNT_DIR"] = counts
        first = medial.batch.run("sqm", [self.inputs], out, workers=1, medial=stand_in)
        resumed = medial.batch.run("sqm", [self.inputs], out, workers=1, medial=stand_in, resume=True)
        self.assertEqual(run_count(counts, "a.vtp"), 1, "read back, not run again")
        for rows_ in (first, resumed):
            by_name = {os.path.basename(r.input): r for r in rows_}
            done, crashed = by_name["a.vtp"], by_name["abort.vtp"]
            self.assertIsInstance(done, medial.batch.Row)
            self.assertEqual((done.status, done.exit_code, done.timings), ("ok", 0, {"total": 0.01}))
            self.assertIsInstance(done.exit_code, int)
            self.assertIsInstance(done.seconds, float)
            self.assertEqual(done["status"], "ok", "rows still read like the dictionaries they were")
            self.assertEqual((crashed.status, crashed.exit_code), ("crash", -6))

    def test_centerline_outputs_pass_through_with_the_stem(self):
        for name in ("u", "helix"):
            shutil.copy(os.path.join(TUBES, name + ".nii.gz"), self.inputs)
        out = os.path.join(self.dir, "out")
        r = self.batch("centerline", self.inputs, "--out-dir", out, "--workers", "2", "--label", "1",
                       "--markups", "{stem}.mrk.json", "--profile", "{stem}-profile.csv")
        self.assertEqual(r.returncode, 0, r.stderr)
        for name in ("u", "helix"):
            with open(os.path.join(out, name + ".mrk.json")) as f:
                curve = json.load(f)["markups"][0]
            self.assertEqual(curve["type"], "Curve")
            self.assertGreater(len(curve["controlPoints"]), 50)
            self.assertTrue(os.path.getsize(os.path.join(out, name + "-profile.csv")) > 100)

    def test_option_arity_comes_from_the_commands_option_table(self):
        import medial.batch
        with_value = medial.batch._options_with_value("sqm")
        self.assertIn("--subdivide", with_value)
        self.assertIn("-o", with_value)
        self.assertNotIn("--union", with_value)
        self.assertNotIn("--quiet", with_value)

    def test_killing_the_driver_leaves_a_valid_manifest(self):
        stand_in, counts = self.stand_in()
        for k in range(30):
            open(os.path.join(self.inputs, "slow%02d.vtp" % k), "w").close()
        out = os.path.join(self.dir, "out")
        env = dict(os.environ, MEDIAL_EXECUTABLE=stand_in, COUNT_DIR=counts)
        driver = subprocess.Popen([MEDIAL, "batch", "sqm", self.inputs, "--out-dir", out, "--workers", "1"],
                                  env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                                  start_new_session=True)
        deadline = time.monotonic() + 120
        while time.monotonic() < deadline and (not os.path.exists(os.path.join(out, "manifest.csv")) or
                                               len(rows(out)) < 3):
            time.sleep(0.2)
        os.killpg(driver.pid, signal.SIGKILL)  # the driver and its cluster, half-way
        driver.wait()
        table = rows(out)
        self.assertGreaterEqual(len(table), 3)
        self.assertLess(len(table), 30)
        for row in table.values():
            self.assertEqual(row["status"], "ok")
            self.assertTrue(os.path.exists(row["output"]))

    def test_usage_errors_exit_two(self):
        for args in ([], ["frobnicate", "x", "--out-dir", self.dir], ["sqm", "x"],
                     ["sqm", "x", "--out-dir", self.dir, "--workers", "0"]):
            r = self.batch(*args)
            if not args:
                continue  # the help
            self.assertEqual(r.returncode, 2, args)
            self.assertIn("see 'medial batch --help'", r.stderr)


if __name__ == "__main__":
    unittest.main()
