"""The test runner's plan (`tools/run_tests.py`): every file in exactly one session, the large
ones alone, the small ones packed, the longest first; a hung session is stopped and failed."""

import os
import sys

import run_tests


def _plan(times, unknown=()):
    run = run_tests.Run("5.2.3", sys.executable, "")
    files = sorted(times) + list(unknown)
    return run_tests._chunks(run, files, times), files


def test_every_file_runs_once_large_ones_alone_small_ones_packed():
    times = {f"tests/test_{i}.py": s for i, s in enumerate((400, 180, 60, 45, 30, 25, 20, 10, 5, 1))}
    jobs, files = _plan(times, unknown=["tests/test_new.py"])
    planned = [f for job in jobs for f in job.files]
    assert sorted(planned) == sorted(files)
    for job in jobs:
        if len(job.files) > 1:
            assert job.estimate <= run_tests.CHUNK_S
            assert all(times.get(f, run_tests.UNKNOWN_S) < run_tests.ALONE_S for f in job.files)
        assert job.estimate == sum(times.get(f, run_tests.UNKNOWN_S) for f in job.files)
    alone = {job.files[0] for job in jobs if len(job.files) == 1 and job.estimate >= run_tests.ALONE_S}
    assert alone == {f for f, s in times.items() if s >= run_tests.ALONE_S}


def test_a_session_past_its_limit_is_stopped_and_failed(monkeypatch):
    monkeypatch.setattr(run_tests, "SESSION_LIMIT_S", 1.0)
    status, output = run_tests._session(["bash", "-c", "echo started; sleep 30"], dict(os.environ))
    assert status == 124
    assert output.startswith("started") and "stopped after 1 s" in output
    assert run_tests._session(["bash", "-c", "echo fine"], dict(os.environ)) == (0, "fine\n")


def test_recording_keeps_each_file_s_largest_cost_over_the_versions(tmp_path, monkeypatch):
    monkeypatch.setattr(run_tests, "DURATIONS", tmp_path / "durations.json")
    monkeypatch.setattr(run_tests, "ROOT", tmp_path)
    older, newer = (run_tests.Run(v, sys.executable, "lts") for v in ("4.2.23", "4.5.15"))
    jobs = [
        run_tests.Job(older, ["tests/test_a.py"], 0.0, cases=[("tests/test_a.py::t1", 10.0, "passed")]),
        run_tests.Job(newer, ["tests/test_a.py"], 0.0, cases=[("tests/test_a.py::t1", 4.0, "passed")]),
    ]
    known = {"all": {"tests/test_b.py": 50.0}}
    run_tests._record(jobs, known)
    assert known == {"all": {"tests/test_b.py": 50.0}, "lts": {"tests/test_a.py": 13.0}}
