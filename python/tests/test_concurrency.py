"""Long calls release the GIL (other Python threads run meanwhile; two calls on two threads
overlap) and stop cleanly on Ctrl-C: KeyboardInterrupt, and a checkpointed ensemble that resumes
to exactly the uninterrupted result."""
import _thread
import os
import signal
import threading
import time

import numpy as np
import pytest

import granular as gr
import granular._progress
from conftest import assert_identical


def count_while(call):
    """Runs `call` on a thread; counts how often this (main) thread gets to run Python meanwhile."""
    done = threading.Event()
    worker = threading.Thread(target=lambda: (call(), done.set()))
    worker.start()
    ticks = 0
    while not done.is_set():
        ticks += 1
        time.sleep(0.001)
    worker.join()
    return ticks


def test_long_calls_let_other_python_threads_run():
    # With the GIL held for the whole call the main thread would not run at all until it ends.
    calls = [
        lambda: gr.ipr_map(xi="0.1:0.4", q=0.5, N=100, realizations=40, threads=1),
        lambda: gr.spectrum(gr.anderson(N=1500), vectors=True),
        lambda: gr.transport(N=201, realizations=40, threads=1, T=1e-3, fit=(2e-4, 1e-3)),
    ]
    for call in calls:
        start = time.monotonic()
        ticks = count_while(call)
        elapsed = time.monotonic() - start
        assert ticks >= max(3, 0.2 * elapsed / 0.001 / 10), (ticks, elapsed)


def test_two_calls_on_two_threads_compute_at_once(monkeypatch):
    """Two IPR maps on two Python threads are both part-way through at one instant.

    Each call's progress is sampled from this (third) thread through the counter its progress bar
    reads. A call that held the GIL would let no other thread run Python from its start to its end, so
    no sample could find it part-way, let alone with the other one part-way too. No times are
    compared: how much two cores speed the pair up is measured by tests/benchmarks/python_vs_cpp.sh."""
    progress = {}  # thread name -> (done(), total) of the call on that thread
    original = gr._progress.run_long

    def recording(work, done, cancel, label, total, bar, *interrupted):
        progress[threading.current_thread().name] = (done, total)
        return original(work, done, cancel, label, total, bar, *interrupted)

    monkeypatch.setattr(gr._progress, "run_long", recording)
    work = dict(xi="0.1:0.6", q=0.5, N=100, realizations=60, threads=1)  # 3,060 chains each
    calls = [threading.Thread(target=lambda: gr.ipr_map(**work), name=f"call {i}") for i in range(2)]
    for call in calls:
        call.start()
    both_part_way = 0
    while any(call.is_alive() for call in calls):
        fractions = [done() / total for done, total in progress.values()]
        if len(fractions) == 2 and all(0 < f < 1 for f in fractions):
            both_part_way += 1
        time.sleep(0.001)
    for call in calls:
        call.join()
    assert len(progress) == 2 and both_part_way > 0, (sorted(progress), both_part_way)


def interrupt_when(condition, how):
    """A watcher thread that interrupts the main thread once condition() holds."""
    def watch():
        deadline = time.monotonic() + 120
        while not condition() and time.monotonic() < deadline:
            time.sleep(0.002)
        how()

    watcher = threading.Thread(target=watch, daemon=True)
    watcher.start()
    return watcher


def records(path):
    if not os.path.exists(path):
        return 0
    with open(path) as f:
        return sum(1 for line in f if line.endswith("\n")) - 1  # minus the header


def test_ctrl_c_during_an_ensemble_leaves_a_resumable_checkpoint(tmp_path):
    checkpoint = str(tmp_path / "run.checkpoint")
    # long enough (~1 s on two idle cores) that the interrupt lands well before the end
    params = dict(disorder="RDM1", N=401, realizations=1500, T=2e-3, fit=(5e-4, 2e-3), threads=2, seed=4)
    watcher = interrupt_when(lambda: records(checkpoint) >= 3, _thread.interrupt_main)
    with pytest.raises(KeyboardInterrupt) as stopped:
        gr.transport(**params, checkpoint=checkpoint, progress=True)
        time.sleep(5)  # finished before the interrupt arrived: let it land here, the test then fails below
    watcher.join()
    # It says how to continue, as the tools print the command (an empty message before).
    assert f"kept in '{checkpoint}'" in str(stopped.value)
    assert "call granular.transport(...) again with the same arguments and resume=True" in str(stopped.value)
    kept = records(checkpoint)
    assert 3 <= kept < 1500, kept
    resumed = gr.transport(**params, checkpoint=checkpoint, resume=True)
    fresh = gr.transport(**params)
    assert resumed.metadata["resumed_checkpoint"] == {"files": [checkpoint]}  # resumed, and from which file
    assert "resumed_checkpoint" not in fresh.metadata
    for key in ("m2", "ipr", "energy_error", "m2_se"):
        assert_identical(resumed[key], fresh[key])
    for key in ("gamma", "gamma_err", "gamma_real_err", "eta", "exponents"):
        assert resumed[key] == fresh[key]
    assert not os.path.exists(checkpoint)  # removed once the run completed


def test_ctrl_c_stops_an_ipr_map_and_the_module_keeps_working():
    started = time.monotonic()
    watcher = interrupt_when(lambda: time.monotonic() - started > 0.3, lambda: os.kill(os.getpid(), signal.SIGINT))
    with pytest.raises(KeyboardInterrupt, match=r"nothing was kept; call granular\.ipr_map\(\.\.\.\) again"):
        gr.ipr_map(xi="0.1:1", q="0.2,0.5,0.8", N=100, realizations=100, threads=2)
        time.sleep(5)
    watcher.join()
    assert time.monotonic() - started < 30
    small = gr.ipr_map(xi=0.5, q=0.5, N=20, realizations=3)
    assert np.all(np.isfinite(small.ipr))


def test_a_checkpoint_of_another_version_is_refused(tmp_path):
    checkpoint = str(tmp_path / "old.checkpoint")
    with open(checkpoint, "w") as f:
        f.write('granular-checkpoint 1 {"granular_commit":"0123456789ab","granular_version":"0.0.9","N":31}\n')
    params = dict(disorder="A", N=31, realizations=2, T=1e-4, fit=(5e-5, 1e-4), threads=1, checkpoint=checkpoint)
    with pytest.raises(ValueError, match=r"made by granular 0\.0\.9 \(commit 0123456789ab\), this is granular "
                       + gr.__version__.replace(".", r"\.")) as refused:
        gr.transport(**params, resume=True)
    assert "resume_other_version" in str(refused.value)
    # Accepted, the version no longer stops it: the parameters (here: other ones) decide.
    with pytest.raises(ValueError, match="different parameters"):
        gr.transport(**params, resume_other_version=True)


def test_a_run_never_writes_over_the_checkpoint_of_an_interrupted_run(tmp_path):
    """The finished realizations of an interrupted run are kept unless the call says to discard them
    (fresh=True) or resumes from them, as the spreading tool's --resume/--fresh."""
    checkpoint = str(tmp_path / "run.checkpoint")
    params = dict(disorder="A", N=31, realizations=3, T=1e-4, fit=(5e-5, 1e-4), threads=1, checkpoint=checkpoint)
    with open(checkpoint, "w") as f:  # what an interrupted run leaves (a header, then its records)
        f.write('granular-checkpoint 1 {"N":31}\n')
    with pytest.raises(ValueError, match=r"checkpoint '.*run\.checkpoint': holds the finished realizations of an "
                       r"interrupted run; continue it with resume, or discard them with fresh"):
        gr.transport(**params)
    with open(checkpoint) as f:
        assert f.read() == 'granular-checkpoint 1 {"N":31}\n'  # untouched
    fresh = gr.transport(**params, fresh=True)
    assert fresh.realizations == 3 and not os.path.exists(checkpoint)
    assert np.array_equal(fresh.m2, gr.transport(**{**params, "checkpoint": None}).m2)
