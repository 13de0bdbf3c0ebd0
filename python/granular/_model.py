"""granular.Material, granular.Chain and the ways of making one; the contact law; bead-type correlations of one
chain: keywords (the tools' option names and units: N, q, xi, seed, realization, F0 [N], R1 [m]), defaults and
docstrings. The values are checked and the chains built by granular._core, with the library's rules."""
import math
import re

import numpy as np

from . import _core
from ._arguments import double_vector
from ._core import Chain, FpuCoefficients, Material, flat_wall, paper_r1, steel

_MAX = 100000000  # beads of a stored chain
_C = _core.ChainChoices()  # the chain table's C++ defaults (chain_parameters()), every constructor's


def _document(cls, doc, **properties):
    """Sets the docstrings of a class of granular._core (or of a Python subclass: its properties documented then
    become its own) and of its properties."""
    cls.__doc__ = doc
    for name, text in properties.items():
        if name in cls.__dict__:
            cls.__dict__[name].__doc__ = text
        else:
            inherited = getattr(cls, name)
            setattr(cls, name, property(inherited.fget, inherited.fset, inherited.fdel, text))


_document(Material, "Elastic material of beads and walls, SI units.\n\nMaterial(young, poisson, density): young: "
          "Young modulus E [Pa]; poisson: Poisson ratio nu [-]; density: rho [kg/m^3]. Defaults: the paper's "
          "stainless steel.", young="Young modulus E [Pa]", poisson="Poisson ratio nu [-]",
          density="mass density rho [kg/m^3]")
_document(Chain, "A chain of N beads between two flat walls under a static precompression F0 (docs/physics.md, 'The chain').\n\n"
          "Beads are indexed 0..N-1 here (bead n+1 of the tools' files); bonds 0..N, bond k joining bead k-1 and "
          "bead k (bond 0 and bond N touch the walls). The arrays are read-only views.\n"
          "Make one with granular.anderson/rdm1/rdm2/homogeneous/diatomic, random_chain, from_types or from_radii.",
          N="number of beads", radius="bead radii R_n [m], N entries",
          mass="bead masses m_n = rho (4/3) pi R_n^3 [kg], N entries", inverse_mass="1/m_n [1/kg], N entries",
          contact="Hertz contact coefficients A_k [N/m^(3/2)] of the N+1 bonds (walls included)",
          overlap="static overlaps Delta_k = (F0/A_k)^(2/3) [m] of the N+1 bonds", F0="static precompression [N]",
          types="bead types (1 or 2) as a uint8 array, or None for a chain built from radii",
          metadata="the chain as the tools describe it in their JSON ('chain' entry): F0_N, R1_m, xi, disorder, q, "
          "seed, realization, N, material, walls")
_document(FpuCoefficients, "Taylor coefficients of the Hertz force about the precompressed state: "
          "F(x) ~ b1 x + b2 x^2 + b3 x^3 (the FPU chain).", b1="(3/2) A^(2/3) F0^(1/3) [N/m]",
          b2="(3/8) A^(4/3) F0^(-1/3) [N/m^2]", b3="-(3/48) A^2 F0^(-1) [N/m^3]",
          modulational_discriminant="3 b1 b3 - 4 b2^2 [N^2/m^4]: band-edge waves are modulationally unstable only "
          "if > 0 (always negative for Hertz)")



def _repr(cls, *names):
    """A repr of a class of granular._core naming its values, as the tools print numbers."""
    cls.__repr__ = lambda x: f"{cls.__name__}({', '.join(f'{n}={_core._format_number(getattr(x, n))}' for n in names)})"


_repr(Material, "young", "poisson", "density")
_material = Material.__init__


def _material_init(self, young=steel.young, poisson=steel.poisson, density=steel.density):
    _material(self)
    self.young, self.poisson, self.density = young, poisson, density


Material.__init__ = _material_init
_repr(FpuCoefficients, "b1", "b2", "b3")
Chain.__repr__ = lambda c: (f"<granular.Chain {c.metadata.get('disorder', 'radii' if c.types is None else 'types')}, "
                            f"N={c.N}, F0={_core._format_number(c.F0)} N>")

_CHAIN_KEYWORDS = """

Keywords (as the tools' options):
    N: beads (>= 2)
    q: probability of a type-1 bead (A), of dimer 11 (RDM1) or of dimer 12 (RDM2), in [0, 1]
    xi: size ratio R2/R1 in (0, 1]
    seed, realization: realization r of seed s is always the same chain (any machine, any thread)
    F0: static precompression [N], >= 0 (0: the sonic vacuum, no linear spectrum)
    R1: radius of type-1 beads [m]; type 2 has xi*R1
    material: granular.Material of beads and walls (default granular.steel)
    walls: "flat" (the paper's) or "sphere" (fixed spheres of the end beads' radius and material: a
        homogeneous chain is then the textbook fixed-end lattice)
Returns a granular.Chain. Raises ValueError naming the keyword when a value is out of range."""


def random_chain(disorder=_C.disorder, N=_C.N, q=_C.q, xi=_C.xi, seed=_C.seed, realization=_C.realization, F0=_C.F0,
                 R1=paper_r1, material=steel, walls=_C.walls):
    recipe = _core.ChainRecipe()
    recipe.disorder = disorder
    recipe.N = _core._size(N, "N", 2, _MAX)
    recipe.q, recipe.xi = q, xi
    recipe.seed = _core._size(seed, "seed")
    realization = _core._size(realization, "realization")
    recipe.F0, recipe.R1, recipe.material = F0, R1, material
    return _core._typed_chain(recipe, realization, walls, "")


def _kind(disorder, name, summary):
    """random_chain with its disorder fixed: the named constructors below."""
    def make(N=_C.N, q=_C.q, xi=_C.xi, seed=_C.seed, realization=_C.realization, F0=_C.F0, R1=paper_r1,
             material=steel, walls=_C.walls):
        return random_chain(disorder, N, q, xi, seed, realization, F0, R1, material, walls)
    make.__name__ = make.__qualname__ = name
    make.__doc__ = summary + _CHAIN_KEYWORDS
    return make


anderson = _kind("A", "anderson", "An Anderson-like chain: each bead type 1 with probability q.")
rdm1 = _kind("RDM1", "rdm1", "A random-dimer chain RDM1: each dimer '1 1' with probability q, else '2 2' (odd N: the "
             "last bead of the last dimer is dropped).")
rdm2 = _kind("RDM2", "rdm2", "A random-dimer chain RDM2: each dimer '1 2' with probability q, else '2 1'.")
homogeneous = _kind("h", "homogeneous", "N type-1 beads (q, xi, seed and realization do not matter).")


random_chain.__doc__ = ("Realization `realization` of seed `seed` of a disorder kind: disorder = 'h' | 'A' | 'RDM1' | "
                        "'RDM2' (the tools' --disorder)." + _CHAIN_KEYWORDS)


def diatomic(N=_C.N, xi=_C.xi, F0=_C.F0, R1=paper_r1, material=steel, walls=_C.walls):
    """Alternating types 1, 2, 1, 2, ...: the ordered chain whose band edges fb1, fb2, fb3 granular.band_edges
    gives. N beads, xi = R2/R1 in (0, 1], F0 [N], R1 [m], walls "flat" or "sphere" (as random_chain)."""
    recipe = _core.ChainRecipe()
    recipe.N = _core._size(N, "N", 2, _MAX)
    recipe.given_types = ([1, 2] * recipe.N)[:recipe.N]
    recipe.xi, recipe.F0, recipe.R1, recipe.material = xi, F0, R1, material
    return _core._typed_chain(recipe, 0, walls, "diatomic")


def _types(values):
    """Bead types 1 or 2 (a list) from any array-like of numbers, ValueError naming `types` otherwise."""
    numbers = double_vector(values, "types", False)
    for i, x in enumerate(numbers):
        if x != 1 and x != 2:
            raise ValueError(f"types: bead {i + 1} has type {_core._format_number(x)} (must be 1 or 2)")
    return [int(x) for x in numbers]


def from_types(types, xi=_C.xi, F0=_C.F0, R1=paper_r1, material=steel, walls=_C.walls):
    """A chain of given bead types: `types` is any array-like of 1 and 2 (type 1 has radius R1 [m], type 2 xi*R1),
    as a --config file holds them. F0 [N]; walls "flat" or "sphere" (as random_chain)."""
    recipe = _core.ChainRecipe()
    recipe.given_types = _types(types)
    recipe.N = max(len(recipe.given_types), 2)
    recipe.xi, recipe.F0, recipe.R1, recipe.material = xi, F0, R1, material
    return _core._typed_chain(recipe, 0, walls, "")


def from_radii(radii, F0=_C.F0, material=steel, walls=_C.walls):
    """A chain of beads of given radii [m] (any 1-D array-like, each finite and > 0) of one material under
    precompression F0 [N], between walls of the same material: "flat", or "sphere" (fixed spheres of the end beads'
    radii)."""
    recipe = _core.ChainRecipe()
    recipe.given_radii = double_vector(radii, "radii")
    if len(recipe.given_radii) < 2:
        raise ValueError(f"radii: {len(recipe.given_radii)} beads; a chain needs at least 2")
    recipe.F0, recipe.material, recipe.walls = F0, material, walls
    return _core._chain(recipe, 0)


def _quasi(kind, modulation, ratio, phase, angle, k0, k0_n_per_m=0.0, keyword="quasi"):
    """A _core.Quasiperiodic of granular.quasiperiodic's keywords, or None for kind None, by the tools' rule for
    --quasi: a keyword that takes no effect on this kind (angle with 's1', modulation without a kind) is refused,
    naming the keyword `keyword` for the kind."""
    c = _core.ChainChoices()
    c.quasi = "" if kind is None else kind
    c.modulation = modulation
    if ratio is not None:  # None: the default (the golden mean)
        c.ratio = ratio if isinstance(ratio, str) else repr(float(ratio))
    c.phase, c.angle, c.k0, c.k0_n_per_m = phase, angle, k0, k0_n_per_m
    try:
        if kind is not None and not kind:
            _core.Quasiperiodic().kind = kind  # the kind's own refusal
        return _core._quasiperiodic(c)
    except ValueError as e:
        if keyword == "quasi":
            raise
        raise ValueError(re.sub(r"\bquasi\b", keyword, str(e))) from None


def quasiperiodic(kind=_core.Quasiperiodic().kind, N=_C.N, modulation=_C.modulation, ratio=_C.ratio, phase=None, angle=_C.angle, k0=_C.k0,
                  seed=_C.seed, realization=_C.realization, F0=_C.F0, R1=paper_r1, material=steel,
                  k0_n_per_m=_C.k0_n_per_m):
    """A quasiperiodic chain (docs/physics.md, "Quasiperiodic chains"), modulated by 1 + modulation*cos(2 pi ratio n
    + phase): kind = 's1' (on-site springs k0*K each, K the bond stiffness), 's2' (masses of spheres of radius R1) or
    'cylinders' (crossing angles angle*(...) [degrees] of cylinders of radius R1, length 2 R1); the tools' --quasi.
    |modulation| < 1; ratio > 0: 'golden', 'p/q' or a number; phase [rad], or None to draw it uniformly in [0, 2 pi)
    from (seed, realization). F0 [N], R1 [m]. k0_n_per_m: 's1' only, the mean on-site stiffness in N/m instead of
    k0*K (0: use k0); the only way to an 's1' chain at F0 = 0 (beads on springs, touching: a Newton's cradle, whose
    breathers granular.breathers computes). Raises ValueError naming the keyword when a value is out of range."""
    recipe = _core.ChainRecipe()
    recipe.R1 = R1
    recipe.N = _core._size(N, "N", 2, _MAX)
    recipe.F0, recipe.material = F0, material
    recipe.seed = _core._size(seed, "seed")
    recipe.quasi = _quasi(kind, modulation, ratio, phase, angle, k0, k0_n_per_m, keyword="kind")
    return _core._chain(recipe, _core._size(realization, "realization"))


def configuration(disorder=_C.disorder, q=_C.q, N=_C.N, seed=_C.seed, realization=_C.realization):
    """The bead types (uint8 array of 1 and 2) of realization `realization` of seed `seed`: what random_chain builds
    its chain from. All xi of one (disorder, q, N, seed, realization) share it."""
    return _core._configuration(disorder, q, _core._size(N, "N", 2, 100000000), _core._size(seed, "seed"),
                                _core._size(realization, "realization"))


def _readable(path):
    """OSError (FileNotFoundError, PermissionError, ...) naming the file when it cannot be opened: the library
    reports an unreadable input file as bad input (the tools' exit code 2), Python as a file error."""
    if isinstance(path, str):
        with open(path):
            pass
    return path


def read_types(path):
    """Bead types from a text file with one type (1 or 2) per line, '#' comments (the tools' --config). Raises
    OSError when it cannot be read, ValueError on a bad line."""
    return _core._read_types(_readable(path))


def read_radii(path):
    """Radii [m] from a text file with one radius per line, '#' comments (the tools' --radii)."""
    return _core._read_radii(_readable(path))


def hertz_coefficient(radius_a, radius_b=flat_wall, material_a=steel, material_b=steel):
    """Hertz contact coefficient A [N/m^(3/2)] of two bodies of radii radius_a, radius_b [m] (force A delta^(3/2) at
    overlap delta); granular.flat_wall (infinity) for a flat wall."""
    if not (radius_a > 0) or not (radius_b > 0):
        raise ValueError(f"{'radius_b' if radius_a > 0 else 'radius_a'}: must be > 0 [m] (granular.flat_wall for a "
                         "wall)")
    return _core._hertz_coefficient(radius_a, radius_b, material_a, material_b)


def static_overlap(contact, F0):
    """Static overlap Delta = (F0/A)^(2/3) [m] of a bond with coefficient A [N/m^(3/2)] under precompression F0
    [N]."""
    return _core._static_overlap(_core._finite(contact, "contact"), _core._finite(F0, "F0"))


def linear_stiffness(contact, F0):
    """Linear stiffness B = (3/2) A^(2/3) F0^(1/3) [N/m] of a bond with coefficient A [N/m^(3/2)] at F0 [N]."""
    return _core._linear_stiffness(_core._finite(contact, "contact"), _core._finite(F0, "F0"))


def fpu_coefficients(contact, F0):
    """FPU coefficients b1, b2, b3 of a bond with coefficient A [N/m^(3/2)] at F0 [N] (both > 0)."""
    return _core._fpu_coefficients(contact, F0)


def nonlinearity_ratio(alpha, contact, F0):
    """epsilon = |alpha|/Delta: a displacement kick alpha [m] relative to the static overlap of a bond with
    coefficient A [N/m^(3/2)] at F0 [N]; infinite at F0 = 0 (no linear limit)."""
    return _core._nonlinearity_ratio(_core._finite(alpha, "alpha"), _core._finite(contact, "contact"),
                                     _core._finite(F0, "F0"))


def cyclic_correlation(types, max_distance=_core.CorrelationConfig().max_distance):
    """Pearson coefficient rho(d), d = 0..max_distance (< N), of the bead types (type 1 -> 0, type 2 -> 1) with their
    cyclic shift by d; `types` is a granular.Chain or an array of 1 and 2. NaN when the chain has one type only."""
    types = (types.types.tolist() if types.types is not None else []) if isinstance(types, Chain) else _types(types)
    if not types:
        raise ValueError("types: the chain was built from radii and has no bead types")
    return _core._cyclic_correlation(types, _core._size(max_distance, "max_distance", 0, len(types) - 1))


def correlation_theory(disorder, q, distance):
    """Infinite-chain rho(d) of a disorder kind at probability q, for one distance or an array of distances [beads];
    NaN where undefined (h; A at q in {0, 1})."""
    if isinstance(distance, int):
        return _core._correlation_theory(disorder, q, distance)
    _core._correlation_theory(disorder, q, 0)  # q and disorder checked first
    distance = double_vector(distance, "distance")
    for i, d in enumerate(distance):
        if d < 0 or d != math.floor(d):
            raise ValueError(f"distance: entry {i} is {_core._format_number(d)} (must be a whole number >= 0)")
    return np.array([_core._correlation_theory(disorder, q, int(d)) for d in distance], dtype=float)
