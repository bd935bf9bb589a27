# Copyright (c) 2026 The CGAL_ext geodesics developers.
"""Threads, progress, cancellation and Ctrl-C.

- The solves release the GIL: a Python thread keeps running during a solve, and two Python
  threads solving at once take less than 0.8 of the time of the same solves one after the other
  (threads=1 in each; retried 5 times before failing), or, on a machine that gives less than two
  cores at that moment, no more than 0.1 above two threads of hashlib's GIL-free work.
- The progress function gets fractions in [0, 1] that never go back, a bounded number of times a
  second; returning False raises Cancelled, and the mesh still gives the right results after.
- Ctrl-C (simulated with _thread.interrupt_main() or a SIGALRM from signal.setitimer) stops a
  long computation with KeyboardInterrupt within 1.5 s, and the mesh still works after.
"""

import _thread
import hashlib
import os
import signal
import threading
import time

import numpy as np
import pytest

import cgal_ext_geodesics as geo

from conftest import grid_mesh

INTERRUPT_AFTER = 0.3  # seconds into the computation
MAX_LATENCY = 1.5  # seconds from the interrupt to KeyboardInterrupt


# ----------------------------------------------------------------------------------------------
# The GIL


def two_threads_against_one_after_the_other(solve_a, solve_b):
    """(seconds one after the other, seconds on two Python threads at once)."""
    t0 = time.perf_counter()
    solve_a()
    solve_b()
    serial = time.perf_counter() - t0
    errors = []

    def run(f):
        try:
            f()
        except BaseException as e:  # noqa: B902 - reported below
            errors.append(e)

    threads = [threading.Thread(target=run, args=(f,)) for f in (solve_a, solve_b)]
    t0 = time.perf_counter()
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    parallel = time.perf_counter() - t0
    assert not errors, f"a solve failed on its thread: {errors[0]!r}"
    return serial, parallel


def hash_work():
    """Work that runs without the GIL in CPython (hashlib on a large buffer): what two threads
    at once give on this machine, now."""
    data = b"x" * (64 << 20)
    return lambda: hashlib.sha256(data).digest()


def python_runs_meanwhile(solve):
    """The share of its own pace at which a pure-Python loop runs on another thread while
    `solve` runs: near 0 when the solve holds the GIL, about 1 (or 1/2 on one free core) when it
    does not."""
    stop = threading.Event()
    count = [0]

    def loop():
        while not stop.is_set():
            count[0] += 1

    t = threading.Thread(target=loop)
    t0 = time.perf_counter()
    t.start()
    time.sleep(0.2)
    stop.set()
    t.join()
    alone = count[0] / (time.perf_counter() - t0)
    stop.clear()
    count[0] = 0
    t = threading.Thread(target=loop)
    t.start()
    t0 = time.perf_counter()
    solve()
    seconds = time.perf_counter() - t0
    stop.set()
    t.join()
    return count[0] / seconds / alone


def assert_gil_released(solve_a, solve_b, what):
    if (os.cpu_count() or 1) < 2:
        pytest.skip(f"os.cpu_count() is {os.cpu_count()}: two threads cannot run at once")
    # 1. Python goes on while the solve runs: whatever the machine's load
    share = max(python_runs_meanwhile(solve_a) for _ in range(2))
    assert share > 0.2, f"{what}: a Python thread ran at {share:.2f} of its pace during the solve: the GIL is held"
    # 2. Two solves at once are faster than one after the other, as much as two threads of work
    # that surely runs without the GIL are on this machine at this moment (a loaded CI machine
    # may give less than two cores)
    two_threads_against_one_after_the_other(solve_a, solve_b)  # warm up: a kept solver for each thread
    timings = []
    for attempt in range(5):
        serial, parallel = two_threads_against_one_after_the_other(solve_a, solve_b)
        h_serial, h_parallel = two_threads_against_one_after_the_other(hash_work(), hash_work())
        timings.append((round(parallel / serial, 2), round(h_parallel / h_serial, 2)))
        if parallel / serial < max(0.8, h_parallel / h_serial + 0.1):
            return
    pytest.fail(f"{what}: two threads at once took (ours, hashlib's) {timings} of the time one after the other "
                f"(must be < 0.8, or within 0.1 of hashlib's): is the GIL released?")


def test_distances_release_the_gil(big_grid):
    V, F, mesh = big_grid
    last = len(V) - 1
    assert_gil_released(lambda: mesh.distances(0, threads=1), lambda: mesh.distances(last, threads=1),
                        "Mesh.distances(threads=1) on 160,000 vertices")


def test_distance_matrix_releases_the_gil(elephant):
    assert_gil_released(lambda: elephant.distance_matrix(np.arange(0, 60), threads=1),
                        lambda: elephant.distance_matrix(np.arange(60, 120), threads=1),
                        "Mesh.distance_matrix(threads=1), 60 rows of elephant.off")


def test_two_threads_solving_at_once_give_the_right_results(big_grid):
    V, F, mesh = big_grid
    sources = [0, len(V) - 1, 1234, 99999]
    expected = {s: mesh.distances(s, threads=1, max_distance=0.4) for s in sources}
    got, errors = {}, []

    def solve(s):
        try:
            for _ in range(2):
                got[s] = mesh.distances(s, threads=1, max_distance=0.4)
        except BaseException as e:  # noqa: B902
            errors.append(e)

    threads = [threading.Thread(target=solve, args=(s,)) for s in sources]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert not errors, repr(errors[0])
    for s in sources:
        assert got[s].tobytes() == expected[s].tobytes(), f"source {s}: another result on a thread"


# ----------------------------------------------------------------------------------------------
# progress


def record_progress(call, answer=True):
    """Runs call(progress); returns (the calls as (seconds since the start, fraction), seconds)."""
    calls = []
    t0 = time.monotonic()

    def progress(done):
        calls.append((time.monotonic() - t0, done))
        return answer

    call(progress)
    return calls, time.monotonic() - t0


def progress_calls(big_grid, elephant):
    V, F, mesh = big_grid
    n = len(V)
    return {
        "distances pvtp threads=1": lambda p: mesh.distances(0, threads=1, progress=p),
        "distances pvtp": lambda p: mesh.distances(0, progress=p),
        "distances vtp": lambda p: mesh.distances(0, algorithm="vtp", progress=p),
        "distances mmp": lambda p: mesh.distances(0, algorithm="mmp", progress=p),
        "distances fwp_mmp": lambda p: mesh.distances(0, algorithm="fwp_mmp", progress=p),
        "distances pmmp": lambda p: mesh.distances(0, algorithm="pmmp", progress=p),
        "paths": lambda p: geo.GeodesicPaths(mesh, [0, n - 1], progress=p),
        "dense matrix": lambda p: elephant.distance_matrix(np.arange(150), threads=1, progress=p),
        "sparse matrix": lambda p: elephant.distance_matrix(np.arange(600), max_distance=0.2, progress=p),
        "voronoi": lambda p: mesh.voronoi([0, n - 1, n // 2], progress=p),
        "sampling": lambda p: mesh.farthest_point_sampling(2, progress=p),
        "patterns": lambda p: elephant.detect_patterns(center=0, radius=0.1, progress=p),
    }


PROGRESS_NAMES = ["distances pvtp threads=1", "distances pvtp", "distances vtp", "distances mmp", "distances fwp_mmp",
                  "distances pmmp", "paths", "dense matrix", "sparse matrix", "voronoi", "sampling", "patterns"]


@pytest.mark.parametrize("name", PROGRESS_NAMES)
def test_progress_fractions(big_grid, elephant, name):
    calls, seconds = record_progress(progress_calls(big_grid, elephant)[name])
    what = f"{name}: {len(calls)} progress calls in {seconds:.2f} s"
    if seconds > 0.3:
        assert calls, f"{what}: the progress function was never called"
    fractions = np.array([f for _, f in calls])
    assert all(isinstance(f, float) for _, f in calls), what
    assert np.all((fractions >= 0) & (fractions <= 1)), f"{what}: fractions out of [0, 1]: {fractions}"
    assert np.all(np.diff(fractions) >= 0), f"{what}: the fraction goes back: {np.round(fractions, 3).tolist()}"
    # a few times a second: at most one call every 0.1 s and those at the end of steps
    assert len(calls) <= 15 * seconds + 5, f"{what}: too many calls"
    # the fraction tells how far the computation is: not near the end at the first report
    if calls and seconds > 0.5:
        first_at, first = calls[0]
        assert first <= first_at / seconds + 0.5, \
            f"{what}: the first report, {first_at:.2f} s in, says {first:.3f} done"


def test_progress_returning_none_or_true_goes_on(elephant):
    expected = elephant.distance_matrix(np.arange(80), threads=1)
    for answer in (None, True, 1):
        calls = []

        def progress(done):
            calls.append(done)
            return answer

        got = elephant.distance_matrix(np.arange(80), threads=1, progress=progress)
        assert calls, "the progress function was never called"
        assert got.tobytes() == expected.tobytes(), f"progress returning {answer!r}"


# ----------------------------------------------------------------------------------------------
# cancellation


@pytest.fixture(scope="module")
def fresh_results(big_grid, elephant_path):
    """fresh_results(key) -> what a Mesh that was never cancelled gives (computed once)."""
    V, F, _ = big_grid
    fresh = {"big": None, "elephant": None}
    cache = {}

    def get(key):
        if key not in cache:
            if key == "matrix":
                fresh["elephant"] = fresh["elephant"] or geo.read_mesh(elephant_path)
                cache[key] = fresh["elephant"].distance_matrix(ELEPHANT_SOURCES)
            else:
                fresh["big"] = fresh["big"] or geo.Mesh(V, F)
                cache[key] = fresh["big"].distances(middle(V), max_distance=0.3, **CHECKS[key])
        return cache[key]

    return get


def middle(V):
    return len(V) // 2 + 200


ELEPHANT_SOURCES = [0, 5, 700]
CHECKS = {
    # after a cancelled computation, these solves must give what a fresh Mesh gives
    "vtp threads=1": dict(threads=1),
    "sequential vtp": dict(algorithm="vtp"),
    "vtp": dict(),
    "lam": dict(lam=2.0),
    "mmp": dict(algorithm="mmp"),
    "fwp_mmp": dict(algorithm="fwp_mmp"),
    "pmmp threads=1": dict(algorithm="pmmp", threads=1),
    "pmmp": dict(algorithm="pmmp"),
}


def cancel_calls(big_grid, elephant):
    V, F, mesh = big_grid
    n = len(V)
    return {
        "distances pvtp threads=1": lambda p: mesh.distances(0, threads=1, progress=p),
        "distances pvtp": lambda p: mesh.distances([0, n - 1], progress=p),
        "distances vtp": lambda p: mesh.distances([0, n - 1], algorithm="vtp", progress=p),
        "distances lam": lambda p: mesh.distances(0, lam=2.0, progress=p),
        "distances mmp": lambda p: mesh.distances(0, algorithm="mmp", progress=p),
        "distances fwp_mmp": lambda p: mesh.distances(0, algorithm="fwp_mmp", progress=p),
        "distances pmmp threads=1": lambda p: mesh.distances(0, algorithm="pmmp", threads=1, progress=p),
        "distances pmmp": lambda p: mesh.distances(0, algorithm="pmmp", progress=p),
        "paths": lambda p: geo.GeodesicPaths(mesh, [0, n - 1], progress=p),
        "dense matrix": lambda p: elephant.distance_matrix(np.arange(400), threads=1, progress=p),
        "sparse matrix": lambda p: elephant.distance_matrix(np.arange(2000), max_distance=0.3, progress=p),
        "voronoi": lambda p: mesh.voronoi([0, n - 1], progress=p),
        "sampling": lambda p: mesh.farthest_point_sampling(3, progress=p),
        "patterns": lambda p: elephant.detect_patterns(center=0, radius=0.1, progress=p),
    }


CANCEL_NAMES = ["distances pvtp threads=1", "distances pvtp", "distances vtp", "distances lam", "distances mmp",
                "distances fwp_mmp", "distances pmmp threads=1", "distances pmmp", "paths", "dense matrix",
                "sparse matrix",
                "voronoi", "sampling", "patterns"]


@pytest.mark.parametrize("name", CANCEL_NAMES)
def test_cancel(big_grid, fresh_results, elephant, name):
    V, F, mesh = big_grid
    call = cancel_calls(big_grid, elephant)[name]
    calls = []

    def stop(done):
        calls.append(done)
        return False

    t0 = time.monotonic()
    with pytest.raises(geo.Cancelled) as info:
        call(stop)
    assert len(calls) == 1, f"{name}: the progress function was called {len(calls)} times after it said stop"
    assert "cancel" in str(info.value), f"{name}: message {info.value}"
    assert not isinstance(info.value, geo.GeodesicError)
    assert time.monotonic() - t0 < 10
    # the meshes still give the results of fresh ones
    checks = {"distances pvtp threads=1": ["vtp threads=1"], "distances pvtp": ["vtp"],
              "distances vtp": ["sequential vtp"], "distances lam": ["lam"],
              "distances mmp": ["mmp"], "distances fwp_mmp": ["fwp_mmp"],
              "distances pmmp threads=1": ["pmmp threads=1"], "distances pmmp": ["pmmp"],
              "dense matrix": ["matrix"], "sparse matrix": ["matrix"],
              "patterns": ["matrix"]}.get(name, ["vtp", "vtp threads=1", "sequential vtp"])
    for check in checks:
        if check == "matrix":
            got = elephant.distance_matrix(ELEPHANT_SOURCES)
        else:
            got = mesh.distances(middle(V), max_distance=0.3, **CHECKS[check])
        assert got.tobytes() == fresh_results(check).tobytes(), f"after cancelling {name}: {check} differs"


def test_a_full_solve_after_a_cancelled_one(big_grid):
    V, F, mesh = big_grid
    fresh_big = geo.Mesh(V, F)
    for threads in (1, None):
        with pytest.raises(geo.Cancelled):
            mesh.distances(0, threads=threads, progress=lambda d: False)
        assert mesh.distances(0, threads=threads).tobytes() == fresh_big.distances(0, threads=threads).tobytes()


# ----------------------------------------------------------------------------------------------
# Ctrl-C


class Interrupted:
    def __init__(self):
        self.latency = None  # seconds from the interrupt to KeyboardInterrupt
        self.finished = None  # seconds the call took when it was not interrupted


def interrupt(call, how="interrupt_main", after=INTERRUPT_AFTER):
    """Runs call() and interrupts it `after` seconds in, as Ctrl-C would."""
    result = Interrupted()
    fired = []
    t0 = time.monotonic()
    if how == "interrupt_main":
        def fire():
            fired.append(time.monotonic())
            _thread.interrupt_main()

        timer = threading.Timer(after, fire)
        old = None
    else:
        def on_alarm(signum, frame):
            fired.append(t0 + after)
            raise KeyboardInterrupt

        old = signal.signal(signal.SIGALRM, on_alarm)
        timer = None
    try:
        try:
            if timer:
                timer.start()
            else:
                signal.setitimer(signal.ITIMER_REAL, after)
            call()
            result.finished = time.monotonic() - t0
        finally:
            if timer:
                timer.cancel()
                timer.join()
            else:
                signal.setitimer(signal.ITIMER_REAL, 0)
            # an interrupt fired just as the call ended is delivered here, not later in pytest
            time.sleep(0.05)
    except KeyboardInterrupt:
        if not fired:
            raise  # a real Ctrl-C
        if result.finished is None:
            result.latency = time.monotonic() - fired[0]
    finally:
        if old is not None:
            signal.signal(signal.SIGALRM, old)
    return result


def assert_interrupted(result, what):
    assert result.finished is None, (f"{what}: finished in {result.finished:.2f} s, before the interrupt "
                                     f"({INTERRUPT_AFTER} s in): the test needs a longer computation")
    assert result.latency is not None, f"{what}: no KeyboardInterrupt"
    assert result.latency < MAX_LATENCY, f"{what}: KeyboardInterrupt {result.latency:.2f} s after the interrupt"


@pytest.mark.parametrize("how", ["interrupt_main", "setitimer"])
@pytest.mark.parametrize("threads", [1, None])
@pytest.mark.parametrize("sparse", [False, True], ids=["dense", "sparse"])
def test_interrupt_a_distance_matrix(elephant, elephant_path, how, threads, sparse):
    # every vertex a source: 2,775 solves, many seconds
    max_distance = 0.5 if sparse else None
    result = interrupt(lambda: elephant.distance_matrix(np.arange(elephant.n_vertices), threads=threads,
                                                        max_distance=max_distance), how)
    assert_interrupted(result, f"distance matrix of every vertex of elephant.off, threads={threads}, {how}")
    fresh = geo.read_mesh(elephant_path)
    assert elephant.distances([0, 9], threads=threads).tobytes() == fresh.distances([0, 9], threads=threads).tobytes()
    assert np.array_equal(elephant.distance_matrix([3, 4], max_distance=max_distance, threads=threads).toarray()
                          if sparse else elephant.distance_matrix([3, 4], threads=threads),
                          fresh.distance_matrix([3, 4], max_distance=max_distance, threads=threads).toarray()
                          if sparse else fresh.distance_matrix([3, 4], threads=threads))


@pytest.fixture(scope="module")
def huge_grid():
    """A 1000 x 1000 height field (1,000,000 vertices; a solve takes seconds), prepared."""
    V, F = grid_mesh(1000, seed=11)
    mesh = geo.Mesh(V, F)
    reference = mesh.distances(len(V) // 2, threads=1, max_distance=0.05)
    return V, F, mesh, reference


@pytest.mark.parametrize("threads", [1, None])
def test_interrupt_a_long_solve(huge_grid, threads):
    V, F, mesh, reference = huge_grid
    result = interrupt(lambda: mesh.distances([0, len(V) - 1], threads=threads))
    assert_interrupted(result, f"distances on 1,000,000 vertices, threads={threads}")
    # the mesh still works
    assert mesh.distances(len(V) // 2, threads=1, max_distance=0.05).tobytes() == reference.tobytes()
    d = mesh.distances(len(V) // 2, threads=threads, max_distance=0.05)
    assert d.tobytes() == reference.tobytes()


def test_interrupt_a_long_solve_with_setitimer(huge_grid):
    V, F, mesh, reference = huge_grid
    result = interrupt(lambda: mesh.distances(0, threads=1, lam=8.0), how="setitimer")
    assert_interrupted(result, "approximate distances on 1,000,000 vertices, SIGALRM")
    assert mesh.distances(len(V) // 2, threads=1, max_distance=0.05).tobytes() == reference.tobytes()


def test_interrupt_pmmp_on_threads(huge_grid):
    V, F, mesh, reference = huge_grid
    result = interrupt(lambda: mesh.distances(0, algorithm="pmmp"))
    try:
        assert_interrupted(result, "pmmp distances on 1,000,000 vertices, every core")
    finally:
        assert mesh.distances(len(V) // 2, threads=1, max_distance=0.05).tobytes() == reference.tobytes()


def test_dense_matrix_rows_report_a_few_times_a_second(big_grid):
    # full rows of 160,000 vertices: the rows are handed over (and the progress told) in batches
    # of about a fifth of a second, not of as many rows as fit in memory
    V, F, mesh = big_grid
    times = []
    t0 = time.monotonic()
    m = mesh.distance_matrix(np.linspace(0, len(V) - 1, 12).astype(int), targets=[0, len(V) - 1],
                             progress=lambda done: times.append(time.monotonic()))
    total = time.monotonic() - t0
    assert m.shape == (12, 2)
    gaps = np.diff([t0] + times + [t0 + total])
    assert gaps.max() < 1.0, f"12 full rows in {total:.2f} s: {len(times)} progress calls, largest gap {gaps.max():.2f} s"
