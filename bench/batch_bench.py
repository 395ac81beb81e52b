#!/usr/bin/python3
"""medial batch against a serial loop of `medial` processes, on the same CGAL sample meshes in one run:
a shell-like loop, --workers 1, --workers 2 (local cluster) and a 2-worker loopback cluster
(dask-scheduler + dask-worker on 127.0.0.1). Prints files/s, the speed-up over one worker, and the batch
overhead per file against the loop.

usage: PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 bench/batch_bench.py [--files N] [--command sqm|skeleton]
"""
import argparse
import glob
import os
import shutil
import signal
import socket
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
    args = parser.parse_args()
    meshes = sorted(glob.glob(os.path.join(TOP, "data", "external", "cgal", "meshes", "*.off")),
                    key=os.path.getsize)[: args.files]  # the smallest: the per-file overhead shows most
    if len(meshes) < args.files:
        sys.exit("batch_bench: run scripts/fetch-samples first")
    work = tempfile.mkdtemp(prefix="medial-batch-bench-")
    results = []
    try:
        out = os.path.join(work, "loop")
        os.makedirs(out)
        start = time.monotonic()
        for mesh in meshes:
            subprocess.run([MEDIAL, args.command, mesh, "-o", os.path.join(out, os.path.basename(mesh) + ".vtp"),
                            "--quiet"], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        results.append(("serial loop of medial", time.monotonic() - start))
        for workers in (1, 2):
            seconds = timed([MEDIAL, "batch", args.command] + meshes +
                            ["--out-dir", os.path.join(work, "w%d" % workers), "--workers", str(workers), "--quiet"])
            results.append(("batch --workers %d" % workers, seconds))
        with socket.socket() as s:
            s.bind(("127.0.0.1", 0))
            port = s.getsockname()[1]
        env = dict(os.environ, PYTHONPATH=os.path.join(TOP, "build", "lib", "python3", "dist-packages"))
        started = [subprocess.Popen(["/usr/bin/dask-scheduler", "--host", "127.0.0.1", "--port", str(port),
                                     "--no-dashboard"], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=env)]
        try:
            time.sleep(2)
            for _ in range(2):
                started.append(subprocess.Popen(["/usr/bin/dask-worker", "tcp://127.0.0.1:%d" % port, "--host",
                                                 "127.0.0.1", "--nthreads", "1", "--no-dashboard"],
                                                stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=env))
            time.sleep(4)
            seconds = timed([MEDIAL, "batch", args.command] + meshes + ["--out-dir", os.path.join(work, "cluster"),
                                                                         "--scheduler", "tcp://127.0.0.1:%d" % port,
                                                                         "--quiet"])
            results.append(("batch, 2-worker loopback cluster", seconds))
        finally:
            for process in started:
                process.send_signal(signal.SIGTERM)
            for process in started:
                process.wait()
    finally:
        shutil.rmtree(work, ignore_errors=True)
    one = results[1][1]
    print("medial %s on the %d smallest CGAL sample meshes" % (args.command, len(meshes)))
    print("%-34s %9s %9s %12s" % ("run", "seconds", "files/s", "vs 1 worker"))
    for name, seconds in results:
        print("%-34s %9.2f %9.2f %11.2fx" % (name, seconds, len(meshes) / seconds, one / seconds))
    print("batch overhead per file (--workers 1 against the loop): %.1f %%" %
          (100.0 * (results[1][1] - results[0][1]) / results[0][1]))


if __name__ == "__main__":
    main()
