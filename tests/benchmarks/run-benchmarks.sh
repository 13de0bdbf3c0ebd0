#!/usr/bin/env bash
# Regenerates every performance figure the README quotes, each beside its peer in the same run
# (interleaved, so that load from other users hits both alike), repeated, medians reported, with
# the machine's name, cores and `uptime` before and after, into docs/benchmark-report.md:
#   1. IPR map, per solve: every LAPACK driver vs the fast solver (Google Benchmark, CPU medians);
#   2. IPR map, the default job (27,300 solves): ipr-map --solver fast vs --solver lapack-stevd vs
#      the NumPy/SciPy script (wall, CPU, peak memory);
#   3. dynamics (N = 2501, T = 10 ms): bond kernel, SABA2C step, one realization with and without
#      the active window vs Boost.Odeint, the cost-accuracy curve (Google Benchmark);
#   4. ensembles: a reduced exponents protocol on 1 vs 2 threads and 1 vs 2 MPI ranks (outputs
#      compared byte for byte);
#   5. the paper's study (exponents --compare-paper on its defaults): wall, CPU, peak memory;
#   6. partial spectra: spectrum --near 15 --count 20 per method and N beside SciPy's eigsh on
#      the same matrix;
#   7. Python vs C++: the default IPR map from Python vs ipr-map; 1000 spectrum calls vs C++;
#   8. localization (N = 1e7, 1000 frequencies) vs a NumPy transfer-matrix loop (extrapolated);
#   9. start-up: every tool's `--version` and `import granular` beside `import numpy` (startup.sh);
#  10. no cliffs: cost per unit of work against N for five jobs (cost_per_work.sh), and its figure.
#
#   bash tests/benchmarks/run-benchmarks.sh [BUILD_DIR] [--repeats R] [--output FILE] [--quick]
#                                           [--sections 1,2,6] [--blas reference]
#
# --sections runs only those sections. --blas reference runs ours and the peers on Debian's
# reference BLAS/LAPACK (LD_LIBRARY_PATH to its alternatives' directories) instead of the one the
# alternatives system selects (OpenBLAS after tools/install-deps.sh); the report says which ran.
#
# BUILD_DIR (default build) must be a Release build with -DGRANULAR_BENCHMARKS=ON and the Python
# module (both on by default); sections whose programs are missing say so and are skipped. Run it
# on an idle machine: it takes about an hour (the partial spectra at N = 1e7 and the paper's study
# dominate). --quick runs every section on a tiny configuration, once, into a scratch file unless
# --output is given: a smoke test of this script (ctest runs it), not figures to quote.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=$root/build repeats=3 quick=0 output="" sections="1,2,3,4,5,6,7,8,9,10" blas=selected
while (($#)); do
  case $1 in
    --quick) quick=1 ;;
    --repeats) repeats=$2; shift ;;
    --output) output=$2; shift ;;
    --sections) sections=$2; shift ;;
    --blas) blas=$2; shift ;;
    -h | --help) sed -n '2,32p' "$0"; exit 0 ;;
    -*) echo "run-benchmarks: unknown option $1 (see --help)" >&2; exit 2 ;;
    *) build=$1 ;;
  esac
  shift
done
build=$(cd "$build" && pwd)
case $blas in
  selected) ;;
  reference)
    reference_dirs=/usr/lib/x86_64-linux-gnu/blas:/usr/lib/x86_64-linux-gnu/lapack
    [[ -e /usr/lib/x86_64-linux-gnu/blas/libblas.so.3 ]] ||
      { echo "run-benchmarks: --blas reference: Debian's libblas3 is not installed" >&2; exit 2; }
    export LD_LIBRARY_PATH=$reference_dirs${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH} ;;
  *) echo "run-benchmarks: --blas $blas: selected or reference" >&2; exit 2 ;;
esac
[[ $sections =~ ^[0-9]+(,[0-9]+)*$ ]] || { echo "run-benchmarks: --sections $sections: a list such as 1,2,6" >&2; exit 2; }
want() { [[ ,$sections, == *,$1,* ]]; }  # whether section $1 runs
[[ -x $build/ipr-map ]] || { echo "run-benchmarks: no tools in $build (build first)" >&2; exit 2; }
((quick)) && repeats=1
study_repeats=$repeats
((quick)) || study_repeats=${STUDY_REPEATS:-1}  # the full study takes minutes: once unless asked
[[ -n $output ]] || output=$( ((quick)) && echo "$build/performance-quick.md" || echo "$root/docs/benchmark-report.md")
py=/usr/bin/python3
# The peers at their best: OpenBLAS picks its native kernels when these are unset (some machines
# set them to work around older OpenBLAS builds); our own programs keep the environment as is.
peer=(env -u OPENBLAS_CORETYPE -u OPENBLAS_L2_SIZE)
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
work=$(mktemp -d /tmp/run-benchmarks.XXXXXX)
trap 'rm -rf "$work"' EXIT
doc=$work/doc.md

say() { printf '%s\n' "$@" >>"$doc"; }
progress() { echo "run-benchmarks: $*" >&2; }
# One run of a command, its wall/CPU seconds and peak memory appended to $work/NAME.times.
timed() {  # NAME command...
  local name=$1; shift
  /usr/bin/time -f '%e %U %S %M' -o "$work/time" "$@" >"$work/$name.out" 2>"$work/$name.err" ||
    { progress "failed: $*"; cat "$work/$name.err" >&2; return 1; }
  cat "$work/time" >>"$work/$name.times"
}
# A Markdown table of the runs NAME... (label from $label_NAME), ratios against the first.
table() {
  local args=() name label_var
  for name in "$@"; do
    label_var="label_${name//-/_}"
    args+=("${!label_var}" "$work/$name.times")
  done
  "$py" - "${args[@]}" <<'EOF' >>"$doc"
import statistics, sys
print("\n| program | median wall [s] | ratio | median CPU [s] | peak memory [MB] | every wall [s] |\n|---|---|---|---|---|---|")
first = None
for label, path in zip(sys.argv[1::2], sys.argv[2::2]):
    runs = [[float(x) for x in line.split()] for line in open(path) if line.strip()]
    wall = statistics.median(r[0] for r in runs)
    cpu = statistics.median(r[1] + r[2] for r in runs)
    first = wall if first is None else first
    ratio = f"{wall / first:.2f}x" if first > 0 else "-"  # /usr/bin/time rounds a --quick run to 0.00 s
    print(f"| {label} | {wall:.2f} | {ratio} | {cpu:.2f} | {max(r[3] for r in runs) / 1024:.1f} | "
          f"{' '.join(f'{r[0]:.2f}' for r in runs)} |")
EOF
}
benchmark_table() {  # JSON of Google Benchmark → medians per benchmark
  "$py" - "$1" <<'EOF' >>"$doc"
import json, sys
rows = json.load(open(sys.argv[1]))["benchmarks"]
print("\n| benchmark | median CPU time | unit | counters |\n|---|---|---|---|")
for r in rows:
    if r.get("run_type") == "aggregate" and r.get("aggregate_name") != "median":
        continue
    skip = {"name", "run_name", "run_type", "repetitions", "repetition_index", "threads", "iterations", "real_time",
            "cpu_time", "time_unit", "family_index", "per_family_instance_index", "aggregate_name", "aggregate_unit"}
    counters = ", ".join(f"{k} {v:.4g}" for k, v in r.items() if k not in skip and isinstance(v, (int, float)))
    print(f"| {r['run_name']} | {r['cpu_time']:.4g} | {r['time_unit']} | {counters} |")
EOF
}
missing() { say "" "_Skipped: $1 is missing (configure with -DGRANULAR_BENCHMARKS=ON / the Python module and build)._"; }

uptime_before=$(uptime)
say "<!-- Generated by tests/benchmarks/run-benchmarks.sh: do not edit by hand. -->" \
  "# Performance figures$([ "$blas" = reference ] && echo ' on the reference BLAS')" "" \
  "Regenerate on an idle machine with \`bash tests/benchmarks/run-benchmarks.sh build\` (a Release build" \
  "with \`-DGRANULAR_BENCHMARKS=ON\` and the Python module; \`--repeats R\`, default 3; \`STUDY_REPEATS\` for the" \
  "paper's study, default 1). Every figure is a median over interleaved repetitions beside its peer." "" \
  "- date: $(date -u +%FT%TZ); commit $(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo unknown)$( ((quick)) && echo '; **--quick: tiny configurations, not figures to quote**')" \
  "- machine: $(hostname), $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//'), $(nproc) cores, $(awk '/MemTotal/ {printf "%.0f GiB", $2 / 1048576}' /proc/meminfo)" \
  "- repetitions: $repeats (paper's study: $study_repeats)" \
  "- BLAS (ours, from \`spectrum --version\`): $("$build/spectrum" --version | sed -n 's/^BLAS: //p')" \
  "- BLAS (peers, from threadpoolctl): $("${peer[@]}" "$py" "$root/tests/benchmarks/peer_blas.py")" \
  "- uptime before: \`$uptime_before\`"

# --- 1. IPR map per solve --------------------------------------------------------------------------
if want 1; then
progress "1/10 IPR map per solve"
say "" "## 1. IPR map, per solve (N = 100, CPU per chain)" ""
if [[ -x $build/benchmarks/ipr_map_benchmark ]]; then
  extra=$( ((quick)) && echo "--benchmark_min_time=0.001" || true)
  say "\`benchmarks/ipr_map_benchmark --benchmark_repetitions=$repeats $extra\` (\`_batch4\` rows: 4 chains per iteration)"
  "$build/benchmarks/ipr_map_benchmark" --benchmark_repetitions="$repeats" --benchmark_report_aggregates_only=true \
    $extra --benchmark_out="$work/ipr.json" --benchmark_out_format=json >/dev/null 2>&1
  benchmark_table "$work/ipr.json"
else missing benchmarks/ipr_map_benchmark; fi

fi

# --- 2. IPR map, whole job ---------------------------------------------------------------------------
if want 2; then
progress "2/10 IPR map, whole job"
if ((quick)); then job=(--xi 0.1:1:0.3 --realizations 2) sjob=(--xi-step 0.3 --realizations 2); else job=() sjob=(); fi
say "" "## 2. IPR map, the default job (whole process, 2 threads)" "" \
  "\`ipr-map --threads 2 --solver fast ${job[*]}\` vs \`--solver lapack-stevd\` vs \`ipr_map_scipy.py ${sjob[*]}\`"
label_ipr_fast="ipr-map --solver fast" label_ipr_lapack="ipr-map --solver lapack-stevd"
label_ipr_scipy="ipr_map_scipy.py (1 process)" label_ipr_scipy2="ipr_map_scipy.py --processes 2"
for ((r = 0; r < repeats; r++)); do
  timed ipr_fast "$build/ipr-map" --quiet --threads 2 --solver fast "${job[@]}" --output "$work/fast.csv"
  timed ipr_lapack "$build/ipr-map" --quiet --threads 2 --solver lapack-stevd "${job[@]}" --output "$work/lapack.csv"
  timed ipr_scipy "${peer[@]}" "$py" "$root/tests/benchmarks/ipr_map_scipy.py" "${sjob[@]}" --output "$work/scipy.csv"
  timed ipr_scipy2 "${peer[@]}" "$py" "$root/tests/benchmarks/ipr_map_scipy.py" "${sjob[@]}" --processes 2 --output "$work/scipy2.csv"
done
table ipr_fast ipr_lapack ipr_scipy ipr_scipy2

fi

# --- 3. dynamics -------------------------------------------------------------------------------------
if want 3; then
progress "3/10 dynamics"
say "" "## 3. Dynamics (N = 2501, tau = 1 us, T = 10 ms, F0 = 10 N)" ""
if [[ -x $build/benchmarks/dynamics_benchmark ]]; then
  extra=$( ((quick)) && echo "--benchmark_min_time=0.001 --benchmark_filter=BareBond|Saba2cStep" || true)
  say "\`benchmarks/dynamics_benchmark --benchmark_repetitions=$repeats $extra\`"
  "$build/benchmarks/dynamics_benchmark" --benchmark_repetitions="$repeats" --benchmark_report_aggregates_only=true \
    $extra --benchmark_out="$work/dyn.json" --benchmark_out_format=json >/dev/null 2>&1
  benchmark_table "$work/dyn.json"
else missing benchmarks/dynamics_benchmark; fi

fi

# --- 4. ensembles: threads and ranks -------------------------------------------------------------------
if want 4; then
progress "4/10 ensembles"
if ((quick)); then ens=(--chains A --F0 10 --ic displacement --realizations 4 --N 101 --T 1e-3 --fit 4e-4:1e-3 --bootstrap 10 --profile-F0 none)
else ens=(--chains A,RDM1 --F0 10,0.1 --ic displacement --realizations 200 --profile-F0 none); fi
say "" "## 4. Ensembles: 1 vs 2 workers" "" "\`exponents ${ens[*]} --quiet\` with each setting below"
label_ens_t1="--threads 1" label_ens_t2="--threads 2"
label_ens_m1="mpirun -np 1 … --threads 1" label_ens_m2="mpirun -np 2 … --threads 1"
names=(ens_t1 ens_t2)
for ((r = 0; r < repeats; r++)); do
  timed ens_t1 "$build/exponents" "${ens[@]}" --quiet --threads 1 --output "$work/t1"
  timed ens_t2 "$build/exponents" "${ens[@]}" --quiet --threads 2 --output "$work/t2"
  if command -v mpirun >/dev/null; then
    timed ens_m1 mpirun -np 1 "$build/exponents" "${ens[@]}" --quiet --threads 1 --output "$work/m1"
    timed ens_m2 mpirun -np 2 "$build/exponents" "${ens[@]}" --quiet --threads 1 --output "$work/m2"
    names=(ens_t1 ens_t2 ens_m1 ens_m2)
  fi
done
table "${names[@]}"
same=yes
for o in t2 m1 m2; do [[ ! -e $work/$o.csv ]] || cmp -s "$work/t1.csv" "$work/$o.csv" || same=NO; done
say "" "Outputs of every setting byte-identical: **$same**"

fi

# --- 5. the paper's study ------------------------------------------------------------------------------
if want 5; then
progress "5/10 the paper's study"
if ((quick)); then study=(--chains A --F0 10 --realizations 2 --N 101 --T 1e-3 --fit 4e-4:1e-3 --bootstrap 10 --profile-F0 none)
else study=(); fi
say "" "## 5. The paper's study" "" "\`exponents --compare-paper --quiet ${study[*]}\` (defaults: 15,010 runs)"
label_study="exponents --compare-paper"
for ((r = 0; r < study_repeats; r++)); do
  timed study "$build/exponents" --compare-paper --quiet "${study[@]}" --output "$work/study"
done
table study

fi

# --- 6. partial spectra --------------------------------------------------------------------------------
if want 6; then
progress "6/10 partial spectra"
if ((quick)); then sizes="1000"; else sizes=${PARTIAL_SIZES:-"1e5 1e6 1e7"}; fi
methods="bisect lapack arpack"
grep -q '"slepc"\|slepc' <("$build/spectrum" --help) && methods="$methods slepc"
say "" "## 6. Partial spectra: the 20 modes nearest 15 kHz of an Anderson chain" "" \
  "\`spectrum --N N --near 15 --count 20 --method M\` (whole process) beside SciPy's \`eigsh\` on the same matrix" \
  "(\`scipy_eigsh.py\`: its call alone, and its whole process); sizes: $sizes"
for n in $sizes; do
  n=$(printf '%.0f' "$n")
  names=()
  reps=$repeats
  ((n < 10000000)) || reps=1  # N = 1e7 takes ~20 min per round (SLEPc alone ~10): once
  for ((r = 0; r < reps; r++)); do
    for m in $methods; do
      timed "ps_${m}_$n" "$build/spectrum" --N "$n" --near 15 --count 20 --method "$m" --quiet \
        --output "$work/ps.csv" --dump-matrix "$work/matrix"
      declare "label_ps_${m}_$n=$m, N = $n"
      ((r)) || names+=("ps_${m}_$n")
    done
    timed "ps_scipy_$n" "${peer[@]}" "$py" "$root/tests/benchmarks/scipy_eigsh.py" "$work/matrix" 15 20 "$work/ps.csv"
    grep -oP '"seconds": \K[0-9.e+-]+' "$work/ps_scipy_$n.out" >>"$work/eigsh_$n"
    declare "label_ps_scipy_$n=SciPy eigsh (whole process), N = $n"
    ((r)) || names+=("ps_scipy_$n")
  done
  table "${names[@]}"
  ((reps == repeats)) || say "" "(N = $n: one round only.)"
  say "" "SciPy's eigsh call alone, N = $n: median $(sort -g "$work/eigsh_$n" | awk '{a[NR] = $1} END {print a[int((NR + 1) / 2)]}') s"
done

fi

# --- 7. Python vs C++ ----------------------------------------------------------------------------------
if want 7; then
progress "7/10 Python vs C++"
say "" "## 7. Python vs C++"
if [[ -e $build/python/granular/__init__.py && -x $build/benchmarks/spectrum_loop ]]; then
  if ((quick)); then pjob=(--xi 0.1:1:0.3 --realizations 2) pyjob="xi=[0.1, 0.4, 0.7, 1.0], realizations=2" count=20
  else pjob=() pyjob="" count=1000; fi
  say "" "The default IPR map: \`ipr-map ${pjob[*]}\` vs \`python3 -c \"import granular; granular.ipr_map($pyjob)\"\`"
  label_py_tool="ipr-map" label_py_module="granular.ipr_map() (whole process)"
  for ((r = 0; r < repeats; r++)); do
    timed py_tool "$build/ipr-map" --quiet "${pjob[@]}" --output "$work/pytool.csv"
    PYTHONPATH=$build/python timed py_module "$py" -c "import granular; granular.ipr_map($pyjob)"
  done
  table py_tool py_module
  say "" "| $count spectrum calls on new chains | C++ (spectrum_loop) [s] | Python [s] | ratio |" "|---|---|---|---|"
  for n in 20 100; do
    cpp=$("$build/benchmarks/spectrum_loop" "$n" "$count" "$repeats" | cut -d' ' -f1)
    pys=$(PYTHONPATH=$build/python "$py" "$root/tests/benchmarks/spectrum_loop.py" "$n" "$count" "$repeats")
    say "| N = $n | $cpp | $pys | $(awk -v a="$pys" -v b="$cpp" 'BEGIN {printf "%.2fx", a / b}') |"
  done
else missing "the Python module or benchmarks/spectrum_loop"; fi

fi

# --- 8. localization vs NumPy ------------------------------------------------------------------------
if want 8; then
progress "8/10 localization vs NumPy"
if ((quick)); then ln=10000 nn=1000 freqs=0.5:50:0.5; else ln=10000000 nn=1000000 freqs=0.05:50:0.05; fi
say "" "## 8. Localization: N = $ln, frequencies $freqs kHz" "" \
  "\`localization --config FILE --xi 0.5 --F0 10 --f $freqs --threads 2\` on an Anderson chain of $ln beads, vs" \
  "\`localization_numpy.py\` on its first $nn beads; the NumPy time is extrapolated linearly to $ln (its loop is O(N))."
"$py" "$root/tests/benchmarks/localization_numpy.py" --write-types "$work/chain.types" --N "$ln" --q 0.5 --seed 1
head -n "$nn" "$work/chain.types" >"$work/small.types"
label_loc_tool="localization, N = $ln" label_loc_numpy="NumPy, N = $nn"
for ((r = 0; r < repeats; r++)); do
  timed loc_tool "$build/localization" --config "$work/chain.types" --xi 0.5 --F0 10 --f "$freqs" --threads 2 --quiet \
    --output "$work/loc"
  timed loc_numpy "${peer[@]}" "$py" "$root/tests/benchmarks/localization_numpy.py" --types "$work/small.types" --xi 0.5 --F0 10 \
    --f "$freqs" --output "$work/numpy.csv"
done
table loc_tool loc_numpy
say "" "NumPy extrapolated to N = $ln: $(sort -g "$work/loc_numpy.times" | awk -v k="$((ln / nn))" '{a[NR] = $1} END {printf "%.1f", a[int((NR + 1) / 2)] * k}') s"
fi

# --- 9. start-up ----------------------------------------------------------------------------------------
if want 9; then
progress "9/10 start-up"
startup_repeats=$( ((quick)) && echo 2 || echo 20)
say "" "## 9. Start-up" "" "\`bash tests/benchmarks/startup.sh BUILD $startup_repeats\` (best of $startup_repeats; Python with the" \
  "build's compiled \`.pyc\` files; this environment's PYTHONDONTWRITEBYTECODE: ${PYTHONDONTWRITEBYTECODE:-unset})" "" '```'
bash "$root/tests/benchmarks/startup.sh" "$build" "$startup_repeats" >>"$doc"
say '```'
fi

# --- 10. no cliffs -------------------------------------------------------------------------------------
if want 10; then
progress "10/10 no cliffs"
cost_max=$( ((quick)) && echo 1000 || echo 1e7)
say "" "## 10. No cliffs: cost per unit of work against N" "" \
  "\`COST_MAX_N=$cost_max bash tests/benchmarks/cost_per_work.sh BUILD $repeats\` (whole process, best of $repeats; work units in the script)" ""
COST_MAX_N=$cost_max bash "$root/tests/benchmarks/cost_per_work.sh" "$build" "$repeats" "$work/cost.csv" >/dev/null
say "| job | N | best wall [s] | ns per unit |" "|---|---|---|---|"
tail -n +2 "$work/cost.csv" | awk -F, '{printf "| %s | %d | %.3f | %s |\n", $1, $2, $3, $5}' >>"$doc"
if ((!quick)); then
  "$py" "$root/tests/benchmarks/plot_cost_per_work.py" "$work/cost.csv" -o "$root/docs/figures/cost-per-work.png"
  cp "$work/cost.csv" "$root/docs/results/cost-per-work.csv"
  say "" "Figure: docs/figures/cost-per-work.png; data: docs/results/cost-per-work.csv."
fi
fi

say "" "- uptime after: \`$(uptime)\`"
mkdir -p "$(dirname "$output")"
mv "$doc" "$output"
progress "wrote $output"
