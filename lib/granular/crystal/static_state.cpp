#include "granular/crystal/static_state.hpp"

#include <Eigen/CholmodSupport>
#include <Eigen/Sparse>
#include <algorithm>
#include <cmath>
#include <string>

#include "granular/crystal/detail/contact_kinematics.hpp"
#include "granular/error.hpp"
#include "granular/model/contact_law.hpp"
#include "granular/number_format.hpp"

namespace granular {
namespace {

using detail::contact_block;
using detail::planar_contact;
using detail::wall_normal;

// Unknowns: (ux, uy) of every bead, then the right and the top wall's inward shifts (walls only).
struct Unknowns {
  std::size_t beads = 0;
  bool walls = false;
  std::size_t size() const { return 2 * beads + (walls ? 2 : 0); }
  // Index of a wall's shift, or -1 when it is held (left, bottom).
  long wall_index(WallSide w) const {
    if (w == WallSide::right) return static_cast<long>(2 * beads);
    if (w == WallSide::top) return static_cast<long>(2 * beads + 1);
    return -1;
  }
  bool pinned(std::size_t dof) const { return !walls && dof < 2; }  // periodic: bead 0
};

// Fills the per-contact geometry and forces of `state` at the unknowns z.
void evaluate(const Packing& p, const Unknowns& n, const Eigen::VectorXd& z, StaticState& s) {
  for (std::size_t b = 0; b < n.beads; ++b)
    s.ux[b] = z[static_cast<long>(2 * b)], s.uy[b] = z[static_cast<long>(2 * b + 1)];
  if (n.walls) {
    s.wall_shift[static_cast<std::size_t>(WallSide::right)] = z[n.wall_index(WallSide::right)];
    s.wall_shift[static_cast<std::size_t>(WallSide::top)] = z[n.wall_index(WallSide::top)];
  }
  for (std::size_t k = 0; k < p.contacts.size(); ++k) {
    const BeadContact& c = p.contacts[k];
    const auto g = planar_contact(c, p.spacing, s.ux[c.j] - s.ux[c.i], s.uy[c.j] - s.uy[c.i]);
    s.overlap[k] = g.overlap, s.distance[k] = g.distance, s.nx[k] = g.nx, s.ny[k] = g.ny;
    s.force[k] = hertz_force(c.contact, g.overlap);
    s.stiffness[k] = hertz_stiffness(c.contact, g.overlap);
  }
  for (std::size_t k = 0; k < p.wall_contacts.size(); ++k) {
    const WallContact& c = p.wall_contacts[k];
    const auto nw = wall_normal(c.wall);
    const double delta = c.reference_overlap - (nw[0] * s.ux[c.bead] + nw[1] * s.uy[c.bead]) +
                         s.wall_shift[static_cast<std::size_t>(c.wall)];
    s.wall_overlap[k] = delta;
    s.wall_force[k] = hertz_force(c.contact, delta);
    s.wall_stiffness[k] = hertz_stiffness(c.contact, delta);
  }
}

// Gradient of the energy (minus the net forces) at the state last evaluated.
Eigen::VectorXd gradient(const Packing& p, const Unknowns& n, const StaticState& s) {
  Eigen::VectorXd g = Eigen::VectorXd::Zero(static_cast<long>(n.size()));
  for (std::size_t k = 0; k < p.contacts.size(); ++k) {
    const BeadContact& c = p.contacts[k];
    const double fx = s.force[k] * s.nx[k], fy = s.force[k] * s.ny[k];  // on j; −(fx, fy) on i
    g[static_cast<long>(2 * c.j)] -= fx, g[static_cast<long>(2 * c.j + 1)] -= fy;
    g[static_cast<long>(2 * c.i)] += fx, g[static_cast<long>(2 * c.i + 1)] += fy;
  }
  for (std::size_t k = 0; k < p.wall_contacts.size(); ++k) {
    const WallContact& c = p.wall_contacts[k];
    const auto nw = wall_normal(c.wall);
    g[static_cast<long>(2 * c.bead)] -= s.wall_force[k] * nw[0];
    g[static_cast<long>(2 * c.bead + 1)] -= s.wall_force[k] * nw[1];
    if (const long w = n.wall_index(c.wall); w >= 0) g[w] += s.wall_force[k];
  }
  if (n.walls)
    for (WallSide w : {WallSide::right, WallSide::top}) g[n.wall_index(w)] -= p.wall_load[static_cast<std::size_t>(w)];
  for (std::size_t d = 0; d < 2; ++d)
    if (n.pinned(d)) g[static_cast<long>(d)] = 0;
  return g;
}

// The energy Hessian (with the prestress term: it decides rigidity) at the state last evaluated.
Eigen::SparseMatrix<double> hessian(const Packing& p, const Unknowns& n, const StaticState& s) {
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(16 * p.contacts.size() + 9 * p.wall_contacts.size() + 2);
  auto add = [&](std::size_t r, std::size_t c, double v) {
    if (n.pinned(r) || n.pinned(c)) return;
    t.emplace_back(static_cast<int>(r), static_cast<int>(c), v);
  };
  auto add_block = [&](std::size_t a, std::size_t b, const detail::Block2& k, double sign) {
    add(2 * a, 2 * b, sign * k.xx), add(2 * a, 2 * b + 1, sign * k.xy);
    add(2 * a + 1, 2 * b, sign * k.xy), add(2 * a + 1, 2 * b + 1, sign * k.yy);
  };
  for (std::size_t k = 0; k < p.contacts.size(); ++k) {
    const BeadContact& c = p.contacts[k];
    const auto K = contact_block(s.stiffness[k], s.force[k], s.distance[k], s.nx[k], s.ny[k], true);
    add_block(c.i, c.i, K, 1), add_block(c.j, c.j, K, 1), add_block(c.i, c.j, K, -1), add_block(c.j, c.i, K, -1);
  }
  for (std::size_t k = 0; k < p.wall_contacts.size(); ++k) {
    const WallContact& c = p.wall_contacts[k];
    const auto nw = wall_normal(c.wall);
    const double kn = s.wall_stiffness[k];
    add_block(c.bead, c.bead, {kn * nw[0] * nw[0], kn * nw[0] * nw[1], kn * nw[1] * nw[1]}, 1);
    if (const long w = n.wall_index(c.wall); w >= 0) {
      const auto wi = static_cast<std::size_t>(w);
      add(wi, wi, kn);
      for (std::size_t d = 0; d < 2; ++d) add(wi, 2 * c.bead + d, -kn * nw[d]), add(2 * c.bead + d, wi, -kn * nw[d]);
    }
  }
  for (std::size_t d = 0; d < 2; ++d)
    if (n.pinned(d)) t.emplace_back(static_cast<int>(d), static_cast<int>(d), 1.0);
  const auto size = static_cast<long>(n.size());
  Eigen::SparseMatrix<double> h(size, size);
  h.setFromTriplets(t.begin(), t.end());
  return h;
}

// Max over beads of |net force| / Σ|forces|, and over the free walls of |Σ f − load| / load.
double imbalance(const Packing& p, const Unknowns& n, const StaticState& s, const Eigen::VectorXd& g) {
  std::vector<double> total(n.beads, 0.0);
  for (std::size_t k = 0; k < p.contacts.size(); ++k)
    total[p.contacts[k].i] += s.force[k], total[p.contacts[k].j] += s.force[k];
  for (std::size_t k = 0; k < p.wall_contacts.size(); ++k) total[p.wall_contacts[k].bead] += s.wall_force[k];
  double worst = 0;
  for (std::size_t b = 0; b < n.beads; ++b) {
    if (n.pinned(2 * b) || total[b] == 0) continue;
    worst = std::max(worst, std::hypot(g[static_cast<long>(2 * b)], g[static_cast<long>(2 * b + 1)]) / total[b]);
  }
  if (n.walls)
    for (WallSide w : {WallSide::right, WallSide::top})
      worst = std::max(worst, std::fabs(g[n.wall_index(w)]) / p.wall_load[static_cast<std::size_t>(w)]);
  return worst;
}

double energy(const Packing& p, const Unknowns& n, const StaticState& s) {
  double e = 0;
  for (std::size_t k = 0; k < p.contacts.size(); ++k) e += hertz_energy(p.contacts[k].contact, s.overlap[k]);
  for (std::size_t k = 0; k < p.wall_contacts.size(); ++k)
    e += hertz_energy(p.wall_contacts[k].contact, s.wall_overlap[k]);
  if (n.walls)
    for (WallSide w : {WallSide::right, WallSide::top})
      e -= p.wall_load[static_cast<std::size_t>(w)] * s.wall_shift[static_cast<std::size_t>(w)];
  return e;
}

/// CHOLMOD's supernodal Cholesky (BLAS-3 on dense blocks of the factor): it succeeds exactly when
/// the matrix is positive definite, which is both the Newton step's and the rigidity's test.
using Cholesky = Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>>;

/// Silenced: CHOLMOD prints "not positive definite" to stdout otherwise, a state reported here.
void quiet(Cholesky& llt) {
  llt.cholmod().print = 0;
  llt.cholmod().error_handler = nullptr;
}

bool positive(const Cholesky& llt) { return llt.info() == Eigen::Success; }

[[noreturn]] void not_rigid(const Packing& p, const std::string& why) {
  throw InvalidInput("packing", ": the " + std::string(to_string(p.lattice)) + " " + std::to_string(p.Lx) + " x " +
                                    std::to_string(p.Ly) + " packing with " + std::string(to_string(p.boundary)) +
                                    " is not rigid under its load: " + why);
}

}  // namespace

StaticState static_state(const Packing& p, const StaticConfig& config) {
  if (!(config.tolerance > 0) || !std::isfinite(config.tolerance))
    throw InvalidInput("tolerance", " " + format_number(config.tolerance) + ": must be finite and > 0");
  if (config.max_iterations < 0)
    throw InvalidInput("max_iterations", " " + std::to_string(config.max_iterations) + ": must be >= 0");
  const Unknowns n{p.size(), p.boundary == Boundary::walls};
  StaticState s;
  s.ux.assign(n.beads, 0), s.uy.assign(n.beads, 0);
  for (auto* v : {&s.overlap, &s.force, &s.stiffness, &s.distance, &s.nx, &s.ny}) v->assign(p.contacts.size(), 0);
  for (auto* v : {&s.wall_overlap, &s.wall_force, &s.wall_stiffness}) v->assign(p.wall_contacts.size(), 0);

  Eigen::VectorXd z = Eigen::VectorXd::Zero(static_cast<long>(n.size()));
  evaluate(p, n, z, s);
  Eigen::VectorXd g = gradient(p, n, s);
  Cholesky cholesky;
  quiet(cholesky);
  // The pattern is the contact network's: analyse it once.
  cholesky.analyzePattern(hessian(p, n, s));
  s.imbalance = imbalance(p, n, s, g);
  // A chord Newton: the Hessian is factored again only when the last step was not a full Newton
  // step that cut the imbalance tenfold; otherwise the next step reuses the factors (one solve, not
  // a factorization: the Hessian moves little near the solution, and its factorization dominates).
  bool refactor = true;
  while (s.imbalance > config.tolerance) {
    if (s.iterations == config.max_iterations)
      not_rigid(p, "Newton's method left a force imbalance of " + format_number(s.imbalance) + " after " +
                       std::to_string(s.iterations) + " steps" +
                       (s.imbalance > 0.5 ? " (a bead pushed by contacts it cannot balance: radii spread wider than "
                                            "the static overlap?)"
                                          : ""));
    // Newton's step where the Hessian is positive definite; elsewhere (a start with open contacts
    // and beads that carry nothing, or a saddle) a Levenberg step (H + μI), μ raised until it is.
    const bool fresh = refactor;
    bool levenberg = false;
    if (fresh) {
      const Eigen::SparseMatrix<double> h = hessian(p, n, s);
      cholesky.factorize(h);
      if (!positive(cholesky)) {
        levenberg = true;
        Eigen::SparseMatrix<double> identity(h.rows(), h.cols());
        identity.setIdentity();
        const double scale = h.diagonal().cwiseAbs().maxCoeff();
        for (double mu = 1e-10 * scale;; mu *= 100) {
          if (mu > 1e4 * scale)
            not_rigid(p, "no positive definite step from a force imbalance " + format_number(s.imbalance));
          cholesky.factorize(h + mu * identity);
          if (positive(cholesky)) break;
        }
      }
    }
    const Eigen::VectorXd step = cholesky.solve(-g);
    // Backtracking: a step is taken when it lowers the energy (Armijo) or the force residual. The
    // first guards the Levenberg steps, the second the last Newton steps, where energy changes are
    // below its rounding.
    const double norm = g.norm(), e0 = energy(p, n, s), slope = g.dot(step);
    double t = 1;
    StaticState trial = s;
    Eigen::VectorXd g_trial;
    for (;;) {
      evaluate(p, n, z + t * step, trial);
      g_trial = gradient(p, n, trial);
      if (g_trial.norm() <= (1 - 1e-4 * t) * norm || energy(p, n, trial) <= e0 + 1e-4 * t * slope) break;
      t /= 2;
      if (t < 1e-12) break;
    }
    if (t < 1e-12) {
      if (!fresh) {  // the old factors no longer give a useful step: factor the Hessian here
        refactor = true;
        continue;
      }
      // At the rounding floor no step lowers the residual any more: accept a balanced state.
      if (s.imbalance <= 1e3 * config.tolerance) break;
      not_rigid(p, "no Newton step lowers its force imbalance " + format_number(s.imbalance));
    }
    z += t * step;
    trial.iterations = s.iterations + 1;
    const double before = s.imbalance;
    s = std::move(trial);
    g = std::move(g_trial);
    s.imbalance = imbalance(p, n, s, g);
    refactor = levenberg || t < 1 || s.imbalance > 0.25 * before;
  }
  cholesky.factorize(hessian(p, n, s));
  s.rigid = positive(cholesky);
  if (config.require_rigid && !s.rigid) {
    std::vector<double> carried(n.beads, 0.0);
    for (std::size_t k = 0; k < p.contacts.size(); ++k)
      carried[p.contacts[k].i] += s.force[k], carried[p.contacts[k].j] += s.force[k];
    for (std::size_t k = 0; k < p.wall_contacts.size(); ++k) carried[p.wall_contacts[k].bead] += s.wall_force[k];
    const auto rattlers = std::count(carried.begin(), carried.end(), 0.0);
    not_rigid(p, "its Hessian is not positive definite at equilibrium" +
                     (rattlers > 0 ? " (" + std::to_string(rattlers) + " beads carry no load)" : std::string()) +
                     " (docs/crystals.md, \"Rigidity\")");
  }
  for (std::size_t k = 0; k < s.overlap.size(); ++k)
    if (s.overlap[k] <= 0) s.open_contacts.push_back(k);
  for (std::size_t k = 0; k < s.wall_overlap.size(); ++k)
    if (s.wall_overlap[k] <= 0) s.open_wall_contacts.push_back(k);
  if (config.refuse_open_contacts && (!s.open_contacts.empty() || !s.open_wall_contacts.empty()))
    throw InvalidInput("packing", ": " + std::to_string(s.open_contacts.size()) + " bead contacts and " +
                                      std::to_string(s.open_wall_contacts.size()) +
                                      " wall contacts open at equilibrium (refuse_open_contacts)");
  return s;
}

std::vector<double> bead_imbalance(const Packing& p, const StaticState& s) {
  std::vector<double> fx(p.size(), 0.0), fy(p.size(), 0.0), total(p.size(), 0.0);
  for (std::size_t k = 0; k < p.contacts.size(); ++k) {
    const BeadContact& c = p.contacts[k];
    fx[c.j] += s.force[k] * s.nx[k], fy[c.j] += s.force[k] * s.ny[k];
    fx[c.i] -= s.force[k] * s.nx[k], fy[c.i] -= s.force[k] * s.ny[k];
    total[c.i] += s.force[k], total[c.j] += s.force[k];
  }
  for (std::size_t k = 0; k < p.wall_contacts.size(); ++k) {
    const WallContact& c = p.wall_contacts[k];
    const auto nw = detail::wall_normal(c.wall);
    fx[c.bead] += s.wall_force[k] * nw[0], fy[c.bead] += s.wall_force[k] * nw[1];
    total[c.bead] += s.wall_force[k];
  }
  std::vector<double> out(p.size(), 0.0);
  for (std::size_t b = 0; b < p.size(); ++b)
    if (total[b] > 0) out[b] = std::hypot(fx[b], fy[b]) / total[b];
  return out;
}

}  // namespace granular
