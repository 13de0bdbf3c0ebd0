"""granular.spread with observers: the same numbers as granular.spreading (the spreading tool) on the
same chain and kick, Python observers called at exactly the steps they schedule, and their errors
stopping the run."""
import numpy as np
import pytest

import granular as gr


def test_observers_measure_what_spreading_reports():
    chain = gr.anderson(N=151, F0=10, seed=2)
    run = gr.spreading(chain, site=76, T=1e-3, fit=(4e-4, 1e-3), samples=50, forces_at=[70, 80], force_samples=40)
    spread = gr.EnergySpread(samples=50, site=75, fit=(4e-4, 1e-3))
    forces = gr.Forces([69, 79], samples=40)
    final = gr.FinalState()
    info = gr.spread(chain, gr.displacement_kick(chain, 75, 1e-7), [spread, forces, final], T=1e-3)
    for key in ("t", "m2", "m2_centroid", "ipr", "energy_error"):
        assert np.array_equal(getattr(spread, key), run[key]), key
    assert np.array_equal(forces.force, run.forces["force"])
    assert np.array_equal(final.u, run.final_state["u"])
    assert np.array_equal(final.energy, run.final_state["energy"])
    assert info["steps"] == 1000
    assert info["initial_energy"] == run.initial_energy
    assert spread.max_energy_error == run.max_energy_error


def test_a_python_observer_sees_exactly_its_steps():
    class Recorder(gr.Observer):
        def __init__(self):
            super().__init__()
            self.steps, self.energy, self.finished = [], [], None

        def schedule(self, plan):
            assert (plan.beads, plan.total_steps) == (61, 40)
            return [0, 13, 13, 40, 400]  # a duplicate, T, and a step past T (ignored)

        def observe(self, snapshot):
            self.steps.append(snapshot.step)
            self.energy.append(snapshot.energy.sum())
            assert snapshot.t == snapshot.step * 1e-6

        def finish(self, snapshot):
            self.finished = snapshot.step

    chain = gr.homogeneous(N=61, F0=1)
    recorder = Recorder()
    info = gr.spread(chain, gr.velocity_kick(chain, 30, 8e-3), [recorder], T=40e-6, dt=1e-6, integrator="aba864")
    assert recorder.steps == [0, 13, 40]
    assert recorder.finished == 40
    # E_n sums to H (the wall bonds are at rest: the pulse has not reached them).
    assert recorder.energy[0] == pytest.approx(info["initial_energy"], rel=1e-14)
    assert recorder.energy[-1] == pytest.approx(info["initial_energy"], rel=1e-8)


def test_an_observer_error_stops_the_run():
    class Failing(gr.Observer):
        def __init__(self):
            super().__init__()

        def schedule(self, plan):
            return [5]

        def observe(self, snapshot):
            raise RuntimeError("stop here")

    chain = gr.homogeneous(N=21, F0=1)
    with pytest.raises(RuntimeError, match="stop here"):
        gr.spread(chain, gr.velocity_kick(chain, 10), [Failing()], T=1e-5)


def test_bad_settings_name_their_keyword():
    chain = gr.homogeneous(N=21, F0=1)
    kick = gr.velocity_kick(chain, 10)
    with pytest.raises(ValueError, match="integrator"):
        gr.spread(chain, kick, [], T=1e-5, integrator="euler")
    with pytest.raises(ValueError, match="forces_at"):
        gr.spread(chain, kick, [gr.Forces([21])], T=1e-5)
    with pytest.raises(ValueError, match="dt"):
        gr.spread(chain, kick, [], T=1e-5, dt=0)
    with pytest.raises(ValueError, match="samples"):
        gr.EnergySpread(samples=1)


def test_an_observer_may_keep_its_snapshots():
    """Kept snapshots hold the state of their own time (not a later one, not freed memory)."""
    chain = gr.anderson(N=61, F0=10, seed=3)
    steps = [0, 5, 17, 40]

    class Keeper(gr.Observer):
        def __init__(self, copy_now):
            super().__init__()
            self.copy_now, self.frames = copy_now, []

        def schedule(self, plan):
            return steps

        def observe(self, now):
            self.frames.append((now.step, now.t, now.u.copy(), now.v.copy(), now.energy.copy()) if self.copy_now else now)

    kept, recorded = Keeper(False), Keeper(True)
    for observer in (kept, recorded):
        gr.spread(chain, gr.displacement_kick(chain, 30, 1e-7), [observer], T=40e-6, dt=1e-6)
    assert len(kept.frames) == len(recorded.frames) == len(steps)
    assert not np.array_equal(recorded.frames[1][2], recorded.frames[-1][2])  # the state does move
    for frame, (step, t, u, v, energy) in zip(kept.frames, recorded.frames):
        assert (frame.step, frame.t) == (step, t)
        assert np.array_equal(frame.u, u)
        assert np.array_equal(frame.v, v)
        assert np.array_equal(frame.energy, energy)
