"""Runs the Blender tests in short fresh sessions, as many at once as there are cores.

Why not one pytest session: software EEVEE (llvmpipe) slows down within a long process (the same
541 tests took 1,927 s in six fresh processes and 3,470 s in one), and a session keeps about one
core busy. So the test files are cut into chunks, each chunk is a pytest session of its own, and a
pool of workers (one a core) takes the longest chunk first; the older Blenders' `lts` subsets go
into the same pool. The chunks' sizes come from `tests/durations.json` (seconds a file took, per
selection), which `--record` rewrites from the run's own figures.

`tools/test` calls it (stdlib only, any Python):

    run_tests.py --run 5.2.3=PYTHON [--run 4.2.23=PYTHON:lts ...] [--workers N] [--record] [-- ARGS]

`--run VERSION=PYTHON` runs the selection ARGS give (every test without) with that Blender's
Python; `:lts` adds `-m lts`. Prints a line as each chunk ends, the log of each that failed, the
ten slowest tests and the elapsed time; exits 1 when a test failed or no test ran.
"""

import argparse
import json
import os
import queue
import re
import shutil
import subprocess
import sys
import tempfile
import threading
import time
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
DURATIONS = ROOT / "tests" / "durations.json"
ALONE_S = 45.0  # a file estimated at this or more is a chunk of its own
CHUNK_S = 60.0  # smaller files are packed into chunks of about this much
UNKNOWN_S = 20.0  # a file not in durations.json yet
SESSION_LIMIT_S = 900.0  # a session still running after this is stopped and failed (a hung render)
NOISE = re.compile(r"EGL Error \(0x3009\)|^Warning: .*CUEW|^ALSA lib")


@dataclass
class Run:
    version: str
    python: str
    mark: str  # "" (the selection as given) or "lts"

    @property
    def key(self):
        return self.mark or "all"


@dataclass
class Job:
    run: Run
    files: list
    estimate: float
    rc: int = None
    seconds: float = 0.0
    log: str = ""
    cases: list = field(default_factory=list)  # (nodeid, seconds, outcome)


def _say(text):
    print(f"water_surface: {text}", flush=True)


def _pytest(run, args, env_tmp):
    env = dict(os.environ, TMPDIR=env_tmp, WATER_SURFACE_BLENDER=run.version, PYTHONUNBUFFERED="1")
    marks = ["-m", run.mark] if run.mark else []
    return [run.python, "-m", "pytest", "--ignore=tests/plain", "-p", "no:cacheprovider", *marks, *args], env


def _collect(run, args):
    """The test files the selection holds for this run (one short session: collection only)."""
    tmp = tempfile.mkdtemp(prefix="water_surface_collect_")
    try:
        command, env = _pytest(run, ["--collect-only", "-q", *args], tmp)
        proc = subprocess.run(command, cwd=ROOT, env=env, capture_output=True, text=True)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    files = sorted({line.split("::")[0] for line in proc.stdout.splitlines() if "::" in line})
    if proc.returncode not in (0, 5):
        sys.stdout.write(proc.stdout[-6000:] + proc.stderr[-3000:])
        raise SystemExit(f"water_surface: collecting the tests for Blender {run.version} failed")
    return files


def _chunks(run, files, known):
    """Files packed into jobs: large ones alone, small ones together up to CHUNK_S."""
    timed = sorted(((known.get(f, UNKNOWN_S), f) for f in files), reverse=True)
    jobs = [Job(run, [f], s) for s, f in timed if s >= ALONE_S]
    small = [(s, f) for s, f in timed if s < ALONE_S]
    packs = []
    for s, f in small:
        for pack in packs:
            if pack.estimate + s <= CHUNK_S:
                pack.files.append(f)
                pack.estimate += s
                break
        else:
            packs.append(Job(run, [f], s))
    return jobs + packs


def _read_junit(path):
    cases = []
    if not path.exists():
        return cases
    for case in ET.parse(path).getroot().iter("testcase"):
        module = case.get("classname", "").split(".")
        name = "/".join(module[:2]) + ".py" if len(module) >= 2 else case.get("classname", "")
        outcome = "passed"
        for child in case:
            if child.tag in ("failure", "error"):
                outcome = "failed"
            elif child.tag == "skipped" and outcome == "passed":
                outcome = "skipped"
        cases.append((f"{name}::{case.get('name')}", float(case.get("time", 0.0)), outcome))
    return cases


def _session(command, env):
    """(exit status, output) of one pytest session; one past SESSION_LIMIT_S is stopped (124)."""
    try:
        proc = subprocess.run(
            command,
            cwd=ROOT,
            env=env,
            stdout=subprocess.PIPE,
            stderr=subprocess.STDOUT,
            text=True,
            timeout=SESSION_LIMIT_S,
        )
    except subprocess.TimeoutExpired as stopped:
        output = stopped.output or ""
        if isinstance(output, bytes):
            output = output.decode(errors="replace")
        return 124, f"{output}\nstopped after {SESSION_LIMIT_S:.0f} s: a test hung (the log above)"
    return proc.returncode, proc.stdout


def _work(jobs, args, show_all, done, lock, total):
    while True:
        try:
            job = jobs.get_nowait()
        except queue.Empty:
            return
        tmp = tempfile.mkdtemp(prefix="water_surface_job_")
        os.chmod(tmp, 0o1777)  # as /tmp: the tests that drop root to 'nobody' still reach their files
        junit = Path(tmp) / "junit.xml"
        command, env = _pytest(job.run, ["-q", f"--junitxml={junit}", *args, *job.files], tmp)
        start = time.monotonic()
        job.rc, output = _session(command, env)
        job.seconds = time.monotonic() - start
        job.log = "\n".join(line for line in output.splitlines() if not NOISE.search(line))
        job.cases = _read_junit(junit)
        shutil.rmtree(tmp, ignore_errors=True)
        with lock:
            done.append(job)
            counts = _counts(job.cases)
            names = " ".join(Path(f).name for f in job.files)
            verdict = "ok" if job.rc == 0 else f"FAILED (exit {job.rc})"
            _say(
                f"[{len(done):>2}/{total}] {job.run.version} {'lts ' if job.run.mark else ''}{names}: "
                f"{counts} in {job.seconds:.0f} s, {verdict}"
            )
            if job.rc != 0 or show_all:
                print(job.log, flush=True)


def _name(run):
    return f"{run.version} -m {run.mark}" if run.mark else run.version


def _counts(cases):
    outcomes = [outcome for _, _, outcome in cases]
    parts = [f"{outcomes.count(o)} {o}" for o in ("passed", "failed", "skipped") if outcomes.count(o)]
    return ", ".join(parts) or "no tests"


def _record(done, known):
    """Each file's seconds in this run (its tests' sum, plus a session's start), the larger of the
    versions' where several run the same selection, written over `known`."""
    fresh = {}
    for job in done:
        per_file = {}
        for nodeid, seconds, _ in job.cases:
            name = nodeid.split("::")[0]
            per_file[name] = per_file.get(name, 0.0) + seconds
        table = fresh.setdefault(job.run.key, {})
        for name, seconds in per_file.items():
            table[name] = max(table.get(name, 0.0), round(seconds + 3.0, 1))
    for key, table in fresh.items():
        known.setdefault(key, {}).update(table)
    DURATIONS.write_text(json.dumps(known, indent=1, sort_keys=True) + "\n", encoding="utf-8")
    _say(f"wrote {DURATIONS.relative_to(ROOT)}")


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--run", action="append", required=True, metavar="VERSION=PYTHON[:lts]")
    parser.add_argument("--workers", type=int, default=os.cpu_count() or 1)
    parser.add_argument("--record", action="store_true", help="rewrite tests/durations.json from this run")
    parser.add_argument("args", nargs="*", help="pytest arguments for every session (after --)")
    options = parser.parse_args(argv)
    runs = []
    for spec in options.run:
        version, _, rest = spec.partition("=")
        python, _, mark = rest.partition(":")
        runs.append(Run(version, python, mark))

    start = time.monotonic()
    known = json.loads(DURATIONS.read_text(encoding="utf-8")) if DURATIONS.exists() else {}
    # Collecting once per selection (the newest Blender's Python names the files of each).
    selections = {}
    for run in runs:
        if run.key not in selections:
            selections[run.key] = _collect(Run(runs[0].version, runs[0].python, run.mark), options.args)
    jobs = [job for run in runs for job in _chunks(run, selections[run.key], known.get(run.key, {}))]
    jobs.sort(key=lambda job: job.estimate, reverse=True)
    if not jobs:
        _say("no test selected")
        return 1
    names = ", ".join(_name(run) for run in runs)
    files = sum(len(job.files) for job in jobs)
    _say(f"{files} files in {len(jobs)} sessions on {options.workers} workers ({names})")
    pending = queue.Queue()
    for job in jobs:
        pending.put(job)
    done, lock = [], threading.Lock()
    show_all = "-s" in options.args
    threads = [
        threading.Thread(target=_work, args=(pending, options.args, show_all, done, lock, len(jobs)))
        for _ in range(max(1, options.workers))
    ]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()

    status = 0
    for run in runs:
        cases = [case for job in done if job.run is run for case in job.cases]
        failed = [job for job in done if job.run is run and job.rc != 0]
        busy = sum(job.seconds for job in done if job.run is run)
        _say(f"Blender {_name(run)}: {_counts(cases)} ({busy:.0f} s in sessions)")
        if failed or not any(outcome == "passed" for _, _, outcome in cases):
            status = 1
        for job in failed:
            _say(f"  failed: {' '.join(job.files)} (exit {job.rc})")
    slowest = sorted(
        ((seconds, job.run.version, nodeid) for job in done for nodeid, seconds, _ in job.cases), reverse=True
    )[:10]
    _say("the ten slowest tests (setup + call + teardown):")
    for seconds, version, nodeid in slowest:
        print(f"  {seconds:7.1f} s  {version}  {nodeid}")
    times = ROOT / "out" / "test_times.json"  # every test's seconds, for picking and splitting
    times.parent.mkdir(exist_ok=True)
    rows = sorted(((s, job.run.version, n, o) for job in done for n, s, o in job.cases), reverse=True)
    times.write_text(json.dumps(rows, indent=0) + "\n", encoding="utf-8")
    if options.record and options.args:  # a selection's per-file sums are not the files' costs
        _say("--record skipped: it records the whole suite only, run without a selection")
    elif options.record:
        _record(done, known)
    elapsed = time.monotonic() - start
    _say(
        f"Blender tests: {'passed' if status == 0 else 'FAILED'} in {elapsed / 60:.1f} min ({elapsed:.0f} s)"
    )
    return status


if __name__ == "__main__":
    sys.exit(main())
