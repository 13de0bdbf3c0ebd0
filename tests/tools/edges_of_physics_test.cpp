// Edges of the physics: every tool at the extremes of its parameters — ξ ∈ {0.01, 1},
// q ∈ {0, 1}, F0 ∈ {1e-9, 1e3} N, kicks that part the beads far (α = 1e-4 m, β = 10 m/s), chains of
// 2 and 3 beads, a 10⁷-bead run with the active window, τ past stability. Each cell either gives a
// result checked against an invariant — an analytic spectrum, an exact scaling law (f ∝ ξ^{-4/3}
// for a homogeneous chain of small beads, f ∝ F0^{1/6}), the trace of the dynamical matrix, a
// symmetry, energy conservation — or stops with a one-line message and its exit code (2 bad input,
// 3 numerical failure) and no output file. Never a hang (every run is under `timeout`), a NaN or
// infinity in an output file, or a crash. The README's "Edges of the physics" table lists the cells.
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <numbers>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "tool_runner.hpp"

namespace {

namespace fs = std::filesystem;
using Table = std::map<std::string, std::vector<double>>;

constexpr int ok = 0, bad_input = 2, numerical = 3;

struct Run {
  int code = -1;
  std::string err;
  fs::path dir;
};

/// Runs `tool args` in `dir` under a hard time limit (a hang is a failure, reported as code 137).
Run run_in(const fs::path& dir, const std::string& tool, const std::string& args, int seconds = 120) {
  const std::string err_file = (dir / ".stderr").string();
  const std::string command = "cd '" + dir.string() + std::string("' && timeout -s KILL ") + std::to_string(seconds) +
                              " '" + granular::testing::tool_path(tool) + "' " + args + " >/dev/null 2>'" + err_file +
                              "'";
  const int status = std::system(command.c_str());
  Run r{WIFEXITED(status) ? WEXITSTATUS(status) : -1, granular::testing::read_file(err_file), dir};
  fs::remove(err_file);
  return r;
}

Table read_csv(const fs::path& path) {
  std::ifstream in(path);
  std::string line, cell;
  std::getline(in, line);
  std::vector<std::string> names;
  for (std::stringstream header(line); std::getline(header, cell, ',');) names.push_back(cell);
  Table t;
  while (std::getline(in, line)) {
    std::stringstream row(line);
    for (const auto& name : names) {
      std::getline(row, cell, ',');
      char* end = nullptr;
      const double v = std::strtod(cell.c_str(), &end);
      t[name].push_back(end == cell.c_str() ? std::nan("") : v);  // words (disorder names) as NaN
    }
  }
  return t;
}

nlohmann::json read_json(const fs::path& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

/// No output CSV may hold a NaN or an infinity (HDF5 is binary and skipped). One
/// documented exception: localization's loc_length = 1/λ is written as inf where λ <= 0 (an
/// extended state at this chain length); its lyapunov column must then say λ <= 0.
void expect_finite_outputs(const fs::path& dir) {
  static const std::regex bad(R"((^|[,:\s\[])[-+]?(nan|inf|infinity)($|[,\s\]}]))", std::regex::icase);
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string ext = e.path().extension().string();
    if (ext != ".csv") continue;  // JSON cannot hold NaN (nlohmann writes null) and describes "inf" in words
    std::ifstream in(e.path());
    std::string line, header;
    for (int n = 1; std::getline(in, line); ++n) {
      if (n == 1) header = line;
      if (header.starts_with("freq_khz,lyapunov,lyapunov_err,loc_length,") && n > 1) {
        std::vector<std::string> cells;
        std::stringstream row(line);
        for (std::string cell; std::getline(row, cell, ',');) cells.push_back(cell);
        if (cells.size() > 3 && cells[3] == "inf" && std::strtod(cells[1].c_str(), nullptr) <= 0) cells[3] = "0";
        line.clear();
        for (const auto& cell : cells) line += cell + ",";
      }
      EXPECT_FALSE(std::regex_search(line, bad)) << e.path().filename() << ":" << n << ": " << line;
    }
  }
}

std::size_t output_files(const fs::path& dir) {
  std::size_t n = 0;
  for (const auto& e : fs::directory_iterator(dir))  // a stopped ensemble keeps its checkpoint for --resume
    n += e.path().filename() != "chain.types" && e.path().filename().string().find(".checkpoint") == std::string::npos;
  return n;
}

// --- independent physics (docs/physics.md, "The chain", §3), from the formulas, not from the library -------------------
constexpr double young = 193e9, poisson = 0.3, density = 8027.17, r1 = 4.76e-3;
constexpr double two_pi = 2 * std::numbers::pi;
double hertz(double ra, double rb) {  // rb = 0: a flat wall
  const double k = 2 * young / (3 * (1 - poisson * poisson));
  return k * std::sqrt(rb == 0 ? ra : ra * rb / (ra + rb));
}
double stiffness(double a, double f0) { return 1.5 * std::pow(a, 2.0 / 3) * std::cbrt(f0); }
double mass(double r) { return density * 4.0 / 3 * std::numbers::pi * r * r * r; }

/// Σ_k ω_k² = trace of M^{-1}K: Σ_n (B_n + B_{n+1}) / m_n for beads of the given radii.
double spectrum_trace(const std::vector<double>& radii, double f0) {
  double trace = 0;
  for (std::size_t n = 0; n < radii.size(); ++n) {
    const double left = n == 0 ? hertz(radii[n], 0) : hertz(radii[n - 1], radii[n]);
    const double right = n + 1 == radii.size() ? hertz(radii[n], 0) : hertz(radii[n], radii[n + 1]);
    trace += (stiffness(left, f0) + stiffness(right, f0)) / mass(radii[n]);
  }
  return trace;
}

/// Analytic frequencies [kHz] of a homogeneous chain of 2 or 3 type-1 beads between flat walls.
std::vector<double> small_chain_khz(std::size_t n, double f0) {
  const double bw = stiffness(hertz(r1, 0), f0), b = stiffness(hertz(r1, r1), f0), m = mass(r1);
  std::vector<double> w2;
  if (n == 2) {
    w2 = {bw / m, (bw + 2 * b) / m};
  } else {  // antisymmetric (1,0,-1): (Bw+B)/m; symmetric (a,b,a): a 2x2 block
    const double s = bw + 3 * b, d = std::sqrt(s * s - 8 * b * bw);
    w2 = {(s - d) / (2 * m), (bw + b) / m, (s + d) / (2 * m)};
  }
  std::vector<double> khz;
  for (double x : w2) khz.push_back(std::sqrt(x) / two_pi / 1e3);
  return khz;
}

void expect_near_rel(const std::vector<double>& a, const std::vector<double>& b, double rel, const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (std::size_t i = 0; i < a.size(); ++i)
    EXPECT_NEAR(a[i], b[i], rel * std::max(std::fabs(a[i]), std::fabs(b[i])) + 1e-300) << what << " row " << i;
}

std::vector<double> scaled(std::vector<double> v, double factor) {
  for (double& x : v) x *= factor;
  return v;
}

/// Round-trip text of a number (std::to_string keeps only 6 decimals).
std::string num(double x) {
  std::ostringstream out;
  out.precision(17);
  out << x;
  return out.str();
}

double max_abs(const std::vector<double>& v) {
  double m = 0;
  for (double x : v) m = std::max(m, std::fabs(x));
  return m;
}

// --- the matrix ---------------------------------------------------------------------------------
struct Cell {
  std::string name;
  std::string tool;
  std::string args;
  std::set<int> allowed;                       ///< exit codes that are a correct outcome
  std::function<void(const Run&)> check = {};  ///< invariant of a result (exit 0)
  int seconds = 120;
  std::string stop_says = "";  ///< what a stop's message must say (a regex); "" = the default below
};

/// A time step past stability may be refused (exit 2, naming the stable dt) or stopped by the
/// energy guard (exit 3); either way the message says which.
const std::string stability_words = "energy error|--dt|time step";

void PrintTo(const Cell& c, std::ostream* os) { *os << c.name; }

// Shared cases written once, compared against a second run in the check.
const std::string spectrum_base = "--disorder A --N 60 --seed 3 --quiet --output out.csv";
const std::string map_base = "--disorder A --N 16 --realizations 3 --seed 2 --quiet --output out.csv";
const std::string spread_short = "--N 101 --T 1e-4 --samples 20 --quiet --output out";
const std::string exponents_small =
    "--T 1e-3 --fit 4e-4:1e-3 --t-star 4e-4 --realizations 2 --bootstrap 10 --profile-F0 none --quiet --output out";
const std::string loc_base = "--N 20000 --segments 4 --quiet --output out";

/// The trace check for `spectrum` on a --config chain of `types` (written as chain.types).
std::function<void(const Run&)> trace_check(const std::vector<int>& types, double xi, double f0) {
  return [=](const Run& r) {
    std::vector<double> radii;
    for (int t : types) radii.push_back(t == 1 ? r1 : xi * r1);
    const Table t = read_csv(r.dir / "out.csv");
    double sum = 0;
    for (double f : t.at("freq_khz")) sum += (two_pi * f * 1e3) * (two_pi * f * 1e3);
    EXPECT_EQ(t.at("freq_khz").size(), types.size());
    EXPECT_NEAR(sum / spectrum_trace(radii, f0), 1.0, 1e-9);
  };
}

const std::vector<int> mixed_types{1, 2, 2, 1, 2, 1, 1, 1, 2, 2, 1, 2, 1, 2, 2, 2, 1, 1, 2, 1};

/// Runs a second case of the same tool in a subfolder and returns its CSV.
Table second_run(const Run& r, const std::string& tool, const std::string& args, const std::string& csv = "out.csv") {
  const fs::path dir = r.dir / "peer";
  fs::create_directories(dir);
  const Run peer = run_in(dir, tool, args);
  EXPECT_EQ(peer.code, 0) << peer.err;
  expect_finite_outputs(dir);
  return read_csv(dir / csv);
}

/// The time step the stability rule chose (JSON "time_step_rule"; 1 µs unless past stability).
double chosen_time_step(const Run& r) {
  return read_json(r.dir / "out.json")["time_step_rule"]["time_step_s"].get<double>();
}

/// Spreading (or exponents) JSON: the largest relative energy error of the run.
double spreading_energy_error(const Run& r) {
  const auto meta = read_json(r.dir / "out.json");
  return meta.contains("run") ? meta["run"]["max_energy_error"].get<double>()
                              : meta["ensemble"]["max_energy_error"].get<double>();
}

// Frequencies scale as F0^(1/6) at fixed geometry (Hertz: K ∝ F0^(1/3)) and the modes do not change:
// the run at F0 = 1e-9 N and 1e3 N against a second run at 10 N.
void add_f0_scaling_cells(std::vector<Cell>& v, const std::string& tool, const std::string& name,
                          const std::string& suffix, const std::string& args) {
  for (double f0 : {1e-9, 1e3})
    v.push_back({name + (f0 < 1 ? "1em9" : "1e3") + suffix,
                 tool,
                 args + " --F0 " + (f0 < 1 ? "1e-9" : "1e3"),
                 {ok},
                 [f0, tool, args](const Run& r) {
                   const Table ref = second_run(r, tool, args + " --F0 10");
                   const Table t = read_csv(r.dir / "out.csv");
                   expect_near_rel(t.at("freq_khz"), scaled(ref.at("freq_khz"), std::pow(f0 / 10, 1.0 / 6)), 1e-12, "f");
                   expect_near_rel(t.at("ipr"), ref.at("ipr"), 1e-8, "IPR");
                 }});
}

std::vector<Cell> cells() {
  std::vector<Cell> v;
  // spectrum ----------------------------------------------------------------------------------
  for (double xi : {0.01, 1.0})
    for (double f0 : {1e-9, 1e3}) {
      std::ostringstream name;
      name << "spectrum_trace_xi" << (xi < 1 ? "0_01" : "1") << "_F0_" << (f0 < 1 ? "1em9" : "1e3");
      std::ostringstream args;
      args << "--config chain.types --xi " << xi << " --F0 " << f0 << " --quiet --output out.csv";
      v.push_back({name.str(), "spectrum", args.str(), {ok}, trace_check(mixed_types, xi, f0)});
    }
  v.push_back(
      {"spectrum_q1_at_xi0_01_is_homogeneous", "spectrum", spectrum_base + " --q 1 --xi 0.01", {ok}, [](const Run& r) {
         const Table h = second_run(r, "spectrum", "--disorder h --N 60 --quiet --output out.csv");
         EXPECT_EQ(read_csv(r.dir / "out.csv"), h) << "q = 1: every bead type 1, whatever xi";
       }});
  v.push_back(
      {"spectrum_q0_scales_as_xi_pow_m4_3", "spectrum", spectrum_base + " --q 0 --xi 0.01", {ok}, [](const Run& r) {
         const Table h = second_run(r, "spectrum", "--disorder h --N 60 --quiet --output out.csv");
         const Table t = read_csv(r.dir / "out.csv");
         expect_near_rel(t.at("freq_khz"), scaled(h.at("freq_khz"), std::pow(0.01, -4.0 / 3)), 1e-12, "f");
         expect_near_rel(t.at("ipr"), h.at("ipr"), 1e-9, "IPR");
       }});
  add_f0_scaling_cells(v, "spectrum", "spectrum_F0_", "_scales_as_F0_pow_1_6", spectrum_base + " --q 0.5 --xi 0.5");
  for (std::size_t n : {2u, 3u})
    v.push_back({std::string("spectrum_N") + std::to_string(n) + "_analytic",
                 "spectrum",
                 std::string("--disorder h --N ") + std::to_string(n) + " --quiet --output out.csv",
                 {ok},
                 [n](const Run& r) {
                   const Table t = read_csv(r.dir / "out.csv");
                   expect_near_rel(t.at("freq_khz"), small_chain_khz(n, 10), 1e-11, "f");
                   if (n == 2) expect_near_rel(t.at("ipr"), {0.5, 0.5}, 1e-12, "IPR of (1,±1)/√2");
                 }});
  v.push_back({"spectrum_F0_0_refused", "spectrum", "--F0 0 --quiet --output out.csv", {bad_input}, {}, 120, "--F0 0"});

  // ipr-map ----------------------------------------------------------------------------------
  v.push_back({"ipr_map_xi_0_01_and_1_q_0_and_1", "ipr-map", map_base + " --xi 0.01,1 --q 0,1", {ok}, [](const Run& r) {
                 Table t = read_csv(r.dir / "out.csv");
                 // rows: q-major, then xi, then mode; 16 modes per cell: (q0,xi.01) (q0,xi1) (q1,xi.01) (q1,xi1)
                 ASSERT_EQ(t["freq_khz"].size(), 64u);
                 auto cell = [&](const char* col, int k) {
                   return std::vector<double>(t[col].begin() + 16 * k, t[col].begin() + 16 * (k + 1));
                 };
                 EXPECT_EQ(cell("freq_khz", 2), cell("freq_khz", 3)) << "q = 1 does not depend on xi";
                 EXPECT_EQ(cell("freq_khz", 1), cell("freq_khz", 3)) << "xi = 1 does not depend on q";
                 expect_near_rel(cell("freq_khz", 0), scaled(cell("freq_khz", 1), std::pow(0.01, -4.0 / 3)), 1e-12,
                                 "q = 0: f ∝ xi^-4/3");
                 expect_near_rel(cell("ipr", 0), cell("ipr", 1), 1e-9, "q = 0: same modes");
               }});
  add_f0_scaling_cells(v, "ipr-map", "ipr_map_F0_", "", map_base + " --xi 0.3 --q 0.5");
  for (std::size_t n : {2u, 3u})
    v.push_back({std::string("ipr_map_N") + std::to_string(n) + "_analytic",
                 "ipr-map",
                 std::string("--disorder A --q 1 --xi 0.5 --N ") + std::to_string(n) +
                     " --realizations 2 --quiet --output out.csv",
                 {ok},
                 [n](const Run& r) {
                   expect_near_rel(read_csv(r.dir / "out.csv").at("freq_khz"), small_chain_khz(n, 10), 1e-11, "f");
                 }});

  // correlations -----------------------------------------------------------------------------------
  for (const char* q : {"0", "1"})
    v.push_back({std::string("correlations_A_q") + q + "_one_type",
                 "correlations",
                 std::string("--disorder A --q ") + q + " --N 50 --realizations 4 --quiet --output out.csv",
                 {bad_input},
                 {},
                 120,
                 "one bead type"});
  v.push_back({"correlations_RDM2_q1_alternating",
               "correlations",
               "--disorder RDM2 --q 1 --N 50 --realizations 4 --quiet --output out.csv",
               {ok},
               [](const Run& r) {
                 const Table t = read_csv(r.dir / "out.csv");
                 for (std::size_t i = 0; i < t.at("distance").size(); ++i) {
                   const double sign = static_cast<long>(t.at("distance")[i]) % 2 == 0 ? 1.0 : -1.0;
                   EXPECT_NEAR(t.at("rho_mean")[i], sign, 1e-12) << "12 12 12...: rho(d) = (-1)^d";
                   EXPECT_NEAR(t.at("rho_theory")[i], sign, 1e-12);
                 }
               }});
  // Realizations of one type only are skipped (σ² = 0); in the others ρ is exact: N = 2 is "1 2" or
  // "2 1", so ρ(1) = -1; N = 3 has two beads of one type, so ρ(1) = ρ(2) = -1/2 (cyclic shifts).
  for (std::size_t n : {2u, 3u})
    v.push_back(
        {std::string("correlations_A_N") + std::to_string(n) + "_exact",
         "correlations",
         std::string("--disorder A --q 0.5 --N ") + std::to_string(n) + " --realizations 50 --quiet --output out.csv",
         {ok},
         [n](const Run& r) {
           const Table t = read_csv(r.dir / "out.csv");
           ASSERT_EQ(t.at("rho_mean").size(), n) << "d = 0 … N-1 (the default max distance is capped)";
           EXPECT_EQ(t.at("rho_mean")[0], 1.0);
           for (std::size_t d = 1; d < n; ++d) EXPECT_NEAR(t.at("rho_mean")[d], n == 2 ? -1.0 : -0.5, 1e-14);
         }});

  // spreading --------------------------------------------------------------------------------------
  // The Hertz force is not odd (compression ≠ extension), so a kicked Hertz chain does not spread
  // symmetrically even when homogeneous; the linear force law does (m2 about n0 = about the centroid).
  const auto energy_below = [](double bound) {
    return [bound](const Run& r) { EXPECT_LT(spreading_energy_error(r), bound); };
  };
  const auto same_as_homogeneous = [](const Run& r) {
    EXPECT_EQ(read_csv(r.dir / "out.csv"), second_run(r, "spreading", spread_short + " --disorder h"))
        << "every bead type 1: the homogeneous chain, bit for bit";
  };
  // ξ = 0.01: type-2 beads ring at ~21 MHz, so the default 1 µs is past stability; the rule divides it.
  v.push_back(
      {"spreading_xi_0_01_default_dt_by_the_rule", "spreading", spread_short + " --xi 0.01", {ok}, [](const Run& r) {
         EXPECT_LT(chosen_time_step(r), 1e-8) << "1 µs / k";
         EXPECT_LT(spreading_energy_error(r), 1e-3) << "under the guard (the rule's step gives ~1e-4)";
       }});
  v.push_back({"spreading_xi_0_01_small_dt",
               "spreading",
               "--N 101 --xi 0.01 --dt 1e-9 --T 2e-6 --samples 20 --quiet --output out",
               {ok},
               energy_below(1e-6)});
  v.push_back({"spreading_xi_1_is_homogeneous", "spreading", spread_short + " --xi 1", {ok}, same_as_homogeneous});
  v.push_back({"spreading_q1_is_homogeneous", "spreading", spread_short + " --q 1 --xi 0.01", {ok}, same_as_homogeneous});
  v.push_back(
      {"spreading_q0_small_beads", "spreading", spread_short + " --q 0 --xi 0.5 --dt 2e-7", {ok}, energy_below(1e-6)});
  v.push_back({"spreading_F0_1em9", "spreading", spread_short + " --F0 1e-9", {ok, numerical}, energy_below(1e-3)});
  v.push_back({"spreading_F0_1e3", "spreading", spread_short + " --F0 1e3", {ok, numerical}, energy_below(1e-3)});
  v.push_back(
      {"spreading_F0_1e3_small_dt", "spreading", spread_short + " --F0 1e3 --dt 2.5e-7", {ok}, energy_below(1e-5)});
  v.push_back({"spreading_alpha_1em4", "spreading", spread_short + " --alpha 1e-4", {ok, numerical}, energy_below(1e-3)});
  v.push_back({"spreading_alpha_1em4_small_dt",
               "spreading",
               "--N 101 --T 1e-4 --dt 1e-8 --samples 20 --alpha 1e-4 --quiet --output out",
               {ok},
               energy_below(1e-6)});
  v.push_back(
      {"spreading_beta_10", "spreading", spread_short + " --ic velocity --beta 10", {ok, numerical}, energy_below(1e-3)});
  v.push_back({"spreading_beta_10_small_dt",
               "spreading",
               "--N 101 --T 1e-4 --dt 1e-8 --samples 20 --ic velocity --beta 10 --quiet --output out",
               {ok},
               energy_below(1e-6)});
  v.push_back({"spreading_N2",
               "spreading",
               "--disorder h --N 2 --T 1e-3 --samples 20 --quiet --output out",
               {ok},
               energy_below(1e-6)});
  v.push_back({"spreading_N3_linear_symmetric",
               "spreading",
               "--disorder h --N 3 --T 1e-3 --samples 20 --force-law linear --quiet --output out",
               {ok},
               [](const Run& r) {
                 const Table t = read_csv(r.dir / "out.csv");
                 expect_near_rel(t.at("m2"), t.at("m2_centroid"), 1e-9, "m2 about n0 = about the centroid");
                 EXPECT_LT(spreading_energy_error(r), 1e-6);
               }});
  v.push_back({"spreading_ensemble_F0_1em9",
               "spreading",
               "--N 51 --T 1e-4 --samples 10 --realizations 3 --F0 1e-9 --quiet --output out",
               {ok, numerical},
               energy_below(1e-3)});
  v.push_back({"spreading_dt_past_stability",
               "spreading",
               "--N 101 --dt 1e-4 --fit-step 1e-4 --T 1e-2 --quiet --output out",
               {bad_input, numerical},
               {},
               120,
               stability_words});
  v.push_back({"Long_spreading_1e7_beads_active_window",
               "spreading",
               "--disorder h --N 1e7 --T 1e-4 --samples 20 --quiet --output out",
               {ok},
               [](const Run& r) {
                 // the wave covers a few beads in 0.1 ms: the 10^7-bead chain must give the 1001-bead numbers
                 const Table small = second_run(r, "spreading",
                                                "--disorder h --N 1001 --T 1e-4 --samples 20 "
                                                "--quiet --output out");
                 const Table big = read_csv(r.dir / "out.csv");
                 EXPECT_EQ(big.at("m2"), small.at("m2"));
                 EXPECT_EQ(big.at("ipr"), small.at("ipr"));
                 expect_near_rel(big.at("m2_centroid"), small.at("m2_centroid"), 1e-12, "m2 about the centroid");
                 const auto window = read_json(r.dir / "out.json")["run"]["window_final"];
                 EXPECT_LT(window[1].get<double>() - window[0].get<double>(), 1000) << "the window stays near the kick";
                 EXPECT_LT(spreading_energy_error(r), 1e-6);
               },
               600});

  // exponents --------------------------------------------------------------------------------------
  // Rows in table order (chains within F0 within kick); two chain kinds that are the same chain
  // must give the same numbers to the bit.
  const auto same_rows = [](std::size_t a, std::size_t b) {
    return [a, b](const Run& r) {
      const Table t = read_csv(r.dir / "out.csv");
      for (const char* col : {"gamma", "gamma_err", "gamma_other", "eta", "eta_err", "max_energy_error"})
        EXPECT_EQ(t.at(col).at(a), t.at(col).at(b)) << col;
      EXPECT_LT(max_abs(t.at("max_energy_error")), 1e-6);
    };
  };
  const auto exponents_energy_below = [](double bound) {
    return [bound](const Run& r) { EXPECT_LT(max_abs(read_csv(r.dir / "out.csv").at("max_energy_error")), bound); };
  };
  v.push_back({"exponents_q1_A_is_h",
               "exponents",
               exponents_small + " --N 51 --chains h,A --q 1 --xi 0.01 --F0 10 --ic displacement",
               {ok},
               same_rows(0, 1)});
  v.push_back({"exponents_q0_A_is_RDM1",
               "exponents",
               exponents_small + " --N 50 --chains A,RDM1 --q 0 --F0 10 --ic displacement --dt 2e-7",
               {ok},
               same_rows(0, 1)});
  v.push_back({"exponents_xi_1_A_is_h",
               "exponents",
               exponents_small + " --N 51 --chains h,A --xi 1 --F0 10 --ic displacement",
               {ok},
               same_rows(0, 1)});
  v.push_back({"exponents_xi_0_01_default_dt_by_the_rule",
               "exponents",
               exponents_small + " --N 51 --chains A --xi 0.01 --F0 10 --ic displacement",
               {ok},
               [](const Run& r) {
                 EXPECT_LT(chosen_time_step(r), 1e-8) << "1 µs / k";
                 EXPECT_LT(max_abs(read_csv(r.dir / "out.csv").at("max_energy_error")), 1e-3) << "under the guard";
               }});
  v.push_back({"exponents_F0_1e3_and_1em9",
               "exponents",
               exponents_small + " --N 51 --chains A --F0 1e3,1e-9",
               {ok, numerical},
               exponents_energy_below(1e-3)});
  v.push_back({"exponents_big_kicks_default_dt",
               "exponents",
               exponents_small + " --N 51 --chains A --F0 10 --alpha 1e-4 --beta 10",
               {ok, numerical},
               exponents_energy_below(1e-3)});
  for (const char* n : {"2", "3"})
    v.push_back({std::string("exponents_N") + n,
                 "exponents",
                 exponents_small + " --chains h,A --F0 10,0 --N " + n,
                 {ok},
                 exponents_energy_below(1e-4)});
  v.push_back({"exponents_dt_past_stability",
               "exponents",
               "--N 51 --T 1e-2 --dt 1e-4 --fit-step 1e-4 --chains A --F0 10 --realizations 2 --profile-F0 none "
               "--quiet --output out",
               {bad_input, numerical},
               {},
               120,
               stability_words});

  // localization -----------------------------------------------------------------------------------
  v.push_back({"localization_q1_homogeneous_band",
               "localization",
               loc_base + " --disorder A --q 1 --xi 0.01 --f 5,10,17,19,25,40",
               {ok},
               [](const Run& r) {
                 const Table t = read_csv(r.dir / "out.csv");
                 const double b = stiffness(hertz(r1, r1), 10), m = mass(r1);
                 for (std::size_t i = 0; i < t.at("freq_khz").size(); ++i) {
                   const double w = two_pi * t.at("freq_khz")[i] * 1e3, x = m * w * w / b;
                   const double lambda =
                       x <= 4 ? 0.0 : std::acosh(x / 2 - 1);  // docs/physics.md, "The linear spectrum"
                   EXPECT_NEAR(t.at("lyapunov")[i], lambda, 2e-3 + 1e-3 * lambda) << t.at("freq_khz")[i] << " kHz";
                   if (x > 4.05) {
                     EXPECT_NEAR(t.at("idos")[i], 1.0, 1e-3) << "every mode lies below";
                   }
                 }
               }});
  v.push_back({"localization_q0_scales_as_xi_pow_m4_3",
               "localization",
               loc_base + std::string(" --disorder A --q 0 --xi 0.01 --f ") + num(17 * std::pow(0.01, -4.0 / 3)) +
                   std::string(",") + num(25 * std::pow(0.01, -4.0 / 3)),
               {ok},
               [](const Run& r) {
                 const Table ref = second_run(r, "localization", loc_base + " --disorder h --f 17,25");
                 expect_near_rel(read_csv(r.dir / "out.csv").at("lyapunov"), ref.at("lyapunov"), 1e-6, "lambda");
               }});
  for (double f0 : {1e-9, 1e3}) {
    const double s = std::pow(f0 / 10, 1.0 / 6);
    v.push_back({std::string("localization_F0_") + (f0 < 1 ? "1em9" : "1e3") + "_scales_as_F0_pow_1_6",
                 "localization",
                 loc_base + " --disorder A --q 0.5 --F0 " + (f0 < 1 ? "1e-9" : "1e3") + " --f " + num(10 * s) +
                     std::string(",") + num(20 * s) + std::string(",") + num(40 * s),
                 {ok},
                 [](const Run& r) {
                   const Table ref = second_run(r, "localization", loc_base + " --disorder A --q 0.5 --f 10,20,40");
                   const Table t = read_csv(r.dir / "out.csv");
                   expect_near_rel(t.at("lyapunov"), ref.at("lyapunov"), 1e-6, "lambda");
                   EXPECT_EQ(t.at("idos"), ref.at("idos")) << "node counts";
                 }});
  }
  for (std::size_t n : {2u, 3u}) {
    // frequencies between the analytic modes: the node count must count the modes below each
    const std::vector<double> f = small_chain_khz(n, 10);
    std::string list = num(0.5 * f[0]);
    for (std::size_t k = 0; k < n; ++k)
      list += std::string(",") + num(k + 1 < n ? 0.5 * (f[k] + f[k + 1]) : 1.5 * f[k]);
    v.push_back({std::string("localization_N") + std::to_string(n) + "_counts_analytic_modes",
                 "localization",
                 std::string("--disorder h --N ") + std::to_string(n) + " --segments 2 --quiet --output out --f " + list,
                 {ok},
                 [n](const Run& r) {
                   const Table t = read_csv(r.dir / "out.csv");
                   for (std::size_t k = 0; k <= n; ++k)
                     EXPECT_NEAR(t.at("idos").at(k) * static_cast<double>(n), static_cast<double>(k), 1e-9);
                 }});
  }
  v.push_back(
      {"localization_F0_0_refused", "localization", loc_base + " --F0 0 --f 10", {bad_input}, {}, 120, "--F0 0"});
  return v;
}

void run_cell(const Cell& c) {
  const fs::path dir = granular::testing::scratch_folder("edges-" + c.name);
  {
    std::ofstream types(dir / "chain.types");
    for (int t : mixed_types) types << t << '\n';
  }
  const Run r = run_in(dir, c.tool, c.args, c.seconds);
  fs::remove(dir / "chain.types");
  ASSERT_NE(r.code, 137) << "hang: killed after " << c.seconds << " s";
  ASSERT_TRUE(c.allowed.contains(r.code)) << "exit " << r.code << ": " << r.err;
  if (r.code != ok) {
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one line: " << r.err;
    EXPECT_NE(r.err.find("error"), std::string::npos) << r.err;
    const std::string says = c.stop_says.empty() ? (r.code == numerical ? stability_words : "error") : c.stop_says;
    EXPECT_TRUE(std::regex_search(r.err, std::regex(says))) << "should say /" << says << "/: " << r.err;
    EXPECT_EQ(output_files(dir), 0u) << "no output after a stop";
  } else {
    expect_finite_outputs(dir);
    if (c.check) c.check(r);
  }
  std::printf("[ cell     ] %s: exit %d%s%s", c.name.c_str(), r.code, r.code ? ", " : "\n", r.code ? r.err.c_str() : "");
  fs::remove_all(dir);
}

std::vector<Cell> cells_named(bool slow) {
  std::vector<Cell> v;
  for (auto& c : cells())
    if (c.name.starts_with("Long_") == slow) v.push_back(c);
  return v;
}

std::string cell_name(const ::testing::TestParamInfo<Cell>& info) { return info.param.name; }

class EdgesOfPhysics : public ::testing::TestWithParam<Cell> {};
TEST_P(EdgesOfPhysics, ResultWithInvariantOrCleanStop) { run_cell(GetParam()); }
INSTANTIATE_TEST_SUITE_P(Matrix, EdgesOfPhysics, ::testing::ValuesIn(cells_named(false)), cell_name);

// The slow cells, in a suite whose full name starts with Long_ so that ctest labels them `long`.
class Long_EdgesOfPhysics : public ::testing::TestWithParam<Cell> {};
TEST_P(Long_EdgesOfPhysics, ResultWithInvariantOrCleanStop) { run_cell(GetParam()); }
INSTANTIATE_TEST_SUITE_P(Long_Matrix, Long_EdgesOfPhysics, ::testing::ValuesIn(cells_named(true)), cell_name);

}  // namespace
