#!/usr/bin/python3
"""medial batch against a serial loop of `medial` processes, on the same CGAL sample meshes in one run:
a shell-like loop, --workers 1, --workers 2 (local cluster) and a 2-worker loopback cluster
(dask-scheduler + dask-worker on 127.0.0.1). Prints files/s, the speed-up over one worker, and the batch
overhead per file against the loop.

The meshes are N of the CGAL samples spread evenly over their sizes (a library as it comes), or with
--smallest the N smallest (each run is mostly process start-up: the worst case for the overhead).

usage: /usr/bin/python3 bench/batch_bench.py [--files N] [--smallest] [--rounds R] [--command skeleton|...]
"""
import argparse
import glob
import os
import shutil
import signal
import socket
import statistics
import subprocess
import sys
import tempfile
import time

TOP = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
MEDIAL = os.path.join(TOP, "build", "bin", "medial")


def timed(command, env=None):
    start = time.monotonic()
    subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=env)
    return time.monotonic() - start


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--files", type=int, default=40)
    parser.add_argument("--command", default="skeleton")
    parser.add_argument("--smallest", action="store_true")
    parser.add_argument("--rounds", type=int, default=3)
    args = parser.parse_args()
    every = sorted(glob.glob(os.path.join(TOP, "data", "external", "cgal", "meshes", "*.off")), key=os.path.getsize)
    if len(every) < args.files:
        sys.exit("batch_bench: run scripts/fetch-samples first")
    if args.smallest:
        meshes = every[: args.files]
    else:
        meshes = [every[k * (len(every) - 1) // max(1, args.files - 1)] for k in range(args.files)]
    work = tempfile.mkdtemp(prefix="medial-batch-bench-")
    env = dict(os.environ, PYTHONPATH=os.path.join(TOP, "build", "lib", "python3", "dist-packages"))
    port = free_port()
    started = start_loopback_cluster(port, env)
    runs = {}  # name -> seconds of each round
    try:
        for round_ in range(args.rounds):
            def out(name):
                path = os.path.join(work, "%s-%d" % (name, round_))
                os.makedirs(path)
                return path
            loop = out("loop")
            start = time.monotonic()
            for mesh in meshes:
                subprocess.run([MEDIAL, args.command, mesh, "-o", os.path.join(loop, os.path.basename(mesh) + ".vtp"),
                                "--quiet"], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
            runs.setdefault("serial loop of medial", []).append(time.monotonic() - start)
            batch = [MEDIAL, "batch", args.command] + meshes + ["--quiet", "--out-dir"]
            for workers in (1, 2):
                runs.setdefault("batch --workers %d" % workers, []).append(
                    timed(batch + [out("w%d" % workers), "--workers", str(workers)]))
            runs.setdefault("batch, 2-worker loopback cluster", []).append(
                timed(batch + [out("cluster"), "--scheduler", "tcp://127.0.0.1:%d" % port]))
    finally:
        for process in started:
            process.send_signal(signal.SIGTERM)
        for process in started:
            process.wait()
        shutil.rmtree(work, ignore_errors=True)
    medians = {name: statistics.median(seconds) for name, seconds in runs.items()}
    one = medians["batch --workers 1"]
    print("medial %s on %d CGAL sample meshes (%s, %.0f kB in all); medians of %d rounds" % (
        args.command, len(meshes), "the smallest" if args.smallest else "spread over the sizes",
        sum(os.path.getsize(m) for m in meshes) / 1e3, args.rounds))
    print("%-34s %9s %9s %12s" % ("run", "seconds", "files/s", "vs 1 worker"))
    for name, seconds in medians.items():
        print("%-34s %9.2f %9.2f %11.2fx" % (name, seconds, len(meshes) / seconds, one / seconds))
    loop = medians["serial loop of medial"]
    print("batch overhead per file (--workers 1 against the loop): %.1f %% (%.0f ms per file)" %
          (100.0 * (one - loop) / loop, 1000.0 * (one - loop) / len(meshes)))


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def start_loopback_cluster(port, env):
    """dask-scheduler and two single-threaded dask-workers on 127.0.0.1; returns their processes."""
    started = [subprocess.Popen(["/usr/bin/dask-scheduler", "--host", "127.0.0.1", "--port", str(port),
                                 "--no-dashboard"], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=env)]
    time.sleep(2)
    for _ in range(2):
        started.append(subprocess.Popen(["/usr/bin/dask-worker", "tcp://127.0.0.1:%d" % port, "--host", "127.0.0.1",
                                         "--nthreads", "1", "--no-dashboard"],
                                        stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=env))
    time.sleep(4)
    return started


if __name__ == "__main__":
    main()
