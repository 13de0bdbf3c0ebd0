"""Chains, the contact law and one chain's correlations: against the formulas of docs/physics.md, "The chain" and "Disorder" and
the library's named constructors as the tools use them."""
import math

import numpy as np
import pytest

import granular as gr
from conftest import assert_identical


def test_anderson_chain_is_realization_of_its_seed_with_the_papers_beads():
    chain = gr.anderson(N=50, q=0.3, xi=0.6, seed=7, realization=2, F0=5.0)
    types = gr.configuration("A", q=0.3, N=50, seed=7, realization=2)
    assert_identical(chain.types, types)
    assert set(np.unique(types)) <= {1, 2}
    r1 = gr.paper_r1
    assert_identical(chain.radius, np.where(types == 1, r1, 0.6 * r1))
    # m = rho 4/3 pi R^3 (steel)
    np.testing.assert_allclose(chain.mass, 8027.17 * 4 / 3 * math.pi * chain.radius**3, rtol=1e-15)
    np.testing.assert_allclose(chain.inverse_mass, 1 / chain.mass, rtol=1e-15)
    assert chain.N == len(chain) == 50 and chain.F0 == 5.0
    assert chain.contact.shape == chain.overlap.shape == (51,)
    # overlap = (F0/A)^(2/3), bulk A from the Hertz formula, walls flat
    np.testing.assert_allclose(chain.overlap, (5.0 / chain.contact) ** (2 / 3), rtol=1e-14)
    assert chain.contact[1] == gr.hertz_coefficient(chain.radius[0], chain.radius[1])
    assert chain.contact[0] == gr.hertz_coefficient(chain.radius[0], gr.flat_wall)
    meta = chain.metadata
    assert (meta["disorder"], meta["q"], meta["seed"], meta["realization"], meta["N"]) == ("A", 0.3, 7, 2, 50)


def test_named_constructors_agree_with_random_chain_and_from_types():
    for name, kind in [("anderson", "A"), ("rdm1", "RDM1"), ("rdm2", "RDM2"), ("homogeneous", "h")]:
        a = getattr(gr, name)(N=31, q=0.4, xi=0.7, seed=3)
        b = gr.random_chain(kind, N=31, q=0.4, xi=0.7, seed=3)
        c = gr.from_types(b.types, xi=0.7)
        for x in (b, c):
            assert_identical(a.radius, x.radius)
            assert_identical(a.contact, x.contact)
    assert set(gr.homogeneous(N=10).types) == {1}
    assert_identical(gr.diatomic(N=6).types, [1, 2, 1, 2, 1, 2])


def test_dimer_chains_are_made_of_dimers():
    t = gr.rdm1(N=40, q=0.5, seed=2).types
    assert np.all(t[0::2] == t[1::2])
    t = gr.rdm2(N=40, q=0.5, seed=2).types
    assert np.all(t[0::2] != t[1::2])


def test_chain_arrays_are_read_only_views_that_keep_the_chain_alive():
    radius = gr.anderson(N=20).radius  # the chain object itself is gone
    assert not radius.flags.writeable
    with pytest.raises(ValueError):
        radius[0] = 1.0
    assert radius.shape == (20,) and np.all(radius > 0)


def test_from_radii_accepts_any_array_like_and_copies_non_contiguous_input():
    radii = np.linspace(2e-3, 5e-3, 40)
    reference = gr.from_radii(radii, F0=3.0)
    for variant in (list(radii), tuple(radii), np.repeat(radii, 2)[::2], np.asfortranarray(radii),
                    radii.astype(np.longdouble), radii.reshape(1, -1)[0]):
        assert_identical(gr.from_radii(variant, F0=3.0).contact, reference.contact)
    assert not np.repeat(radii, 2)[::2].flags.c_contiguous
    assert gr.from_radii(np.array([4, 5], dtype=np.int64) * 1e-3).N == 2
    assert reference.types is None


def test_from_types_accepts_integer_and_whole_float_arrays():
    ref = gr.from_types([1, 2, 2, 1])
    for t in (np.array([1, 2, 2, 1], dtype=np.uint8), np.array([1.0, 2.0, 2.0, 1.0]), np.array([[1, 2, 2, 1]])[0],
              np.array([1, 1, 2, 2, 2, 2, 1, 1])[::2]):
        assert_identical(gr.from_types(t).radius, ref.radius)


def test_types_and_radii_files_read_as_the_tools_read_them(data_dir):
    types = gr.read_types(str(data_dir / "examples" / "diatomic-10.types"))
    assert_identical(types, [1, 2] * 5)
    radii = gr.read_radii(str(data_dir / "examples" / "single-impurity-11.radii"))
    assert radii.shape == (11,)
    with pytest.raises(FileNotFoundError, match="nonexistent"):
        gr.read_types("/nonexistent/file.types")
    with pytest.raises(OSError):
        gr.read_radii("/")


def test_fpu_coefficients_are_the_taylor_expansion_of_hertz():
    A, F0 = gr.hertz_coefficient(gr.paper_r1, gr.paper_r1), 10.0
    f = gr.fpu_coefficients(contact=A, F0=F0)
    delta = gr.static_overlap(A, F0)
    assert f.b1 == gr.linear_stiffness(A, F0)
    # F(x) = A (Delta + x)^(3/2) - F0: compare with the cubic on a small strain
    for x in (1e-3 * delta, 1e-2 * delta):
        exact = A * (delta + x) ** 1.5 - F0
        cubic = f.b1 * x + f.b2 * x**2 + f.b3 * x**3
        assert abs(exact - cubic) < 1e-2 * abs(f.b3 * x**3) + 1e-12 * abs(exact)
    assert f.modulational_discriminant < 0
    assert gr.nonlinearity_ratio(1e-7, A, F0) == pytest.approx(1e-7 / delta, rel=1e-15)
    assert gr.nonlinearity_ratio(1e-7, A, 0.0) == math.inf


def test_single_chain_correlation_of_an_alternating_chain_is_plus_minus_one():
    rho = gr.cyclic_correlation(gr.diatomic(N=20), max_distance=4)
    np.testing.assert_allclose(rho, [1, -1, 1, -1, 1], atol=1e-15)
    assert np.all(np.isnan(gr.cyclic_correlation(gr.homogeneous(N=10), max_distance=2)))
    # RDM1 theory: rho(1) = 1/2 (dimers), rho(2) = 0 at q = 1/2 (independent dimers)
    assert gr.correlation_theory("RDM1", 0.5, 2) == pytest.approx(0.0, abs=1e-15)
    theory = gr.correlation_theory("A", 0.5, np.arange(4))
    assert_identical(theory, [1.0, 0.0, 0.0, 0.0])


def test_sphere_walls_make_the_homogeneous_chain_the_textbook_lattice():
    # f_j / f_N = sin(j pi / 2(N+1)) / sin(N pi / 2(N+1)) needs no material constant (docs/physics.md, "Homogeneous
    # check"); flat walls stiffen the end bonds and move mode 1 off it.
    n = 40
    k = math.pi / (2 * (n + 1))
    lattice = np.sin(np.arange(1, n + 1) * k) / math.sin(n * k)
    for make in (lambda w: gr.homogeneous(N=n, walls=w), lambda w: gr.from_radii([gr.paper_r1] * n, walls=w)):
        f = gr.spectrum(make("sphere")).freq_khz
        np.testing.assert_allclose(f / f[-1], lattice, rtol=1e-12, atol=0)
        flat = gr.spectrum(make("flat")).freq_khz
        assert flat[0] / flat[-1] / lattice[0] - 1 > 1e-3
    assert gr.homogeneous(N=n, walls="sphere").metadata["walls"].startswith("fixed spheres")
    with pytest.raises(ValueError, match="walls"):
        gr.anderson(N=10, walls="round")
