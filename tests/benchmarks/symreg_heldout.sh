#!/usr/bin/env bash
# Held-out rows against overfitting (issue 24, part 3; figures in docs/BENCHMARKS.md, "Symbolic regression on
# users' data").
#
# A user's measurement, as a spreadsheet writes it: ROWS noisy readings of a reflectance curve,
# F(c) = 0.04 + 0.96 (1 - c)^5 + N(0, NOISE), at stratified c = cos(theta) in [0, 1], saved as UTF-8 with a
# byte-order mark, a quoted header and a '+' on every number. A symreg job fits it with test_fraction 0.3
# (SEEDS job seeds, each holding out a different 30 % of the rows). Every front member is then exported as
# C++ (`pbrfit export --format cpp --double`), compiled, and measured against the noise-free curve on 10,001
# points: the error a user would really get, which neither the training nor the test rows show exactly.
# Three ways to pick a member are compared per seed: the most accurate on the training rows (the last of the
# front), the knee (export's default), and the lowest test error (`export --member test`).
#
# Usage: tests/benchmarks/symreg_heldout.sh [path/to/pbrfit]
#        (SEEDS=5, ROWS=48, NOISE=0.01, GENERATIONS=400, RANKS=2)
set -euo pipefail
cd "$(dirname "$0")/../.."
PBRFIT=$(realpath "${1:-build/pbrfit}")
SEEDS=${SEEDS:-5}
ROWS=${ROWS:-48}
NOISE=${NOISE:-0.01}
GENERATIONS=${GENERATIONS:-400}
RANKS=${RANKS:-2}
PYTHON=/usr/bin/python3  # Debian's, with h5py
FLAGS=(--oversubscribe --bind-to none --mca pml ob1 --mca btl self,vader)
[[ $(id -u) -eq 0 ]] && FLAGS+=(--allow-run-as-root)
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT
cd "$OUT"

"$PYTHON" - "$ROWS" "$NOISE" <<'PY'
import random, sys
rows, noise = int(sys.argv[1]), float(sys.argv[2])
rng = random.Random(2026)
with open("data.csv", "w", encoding="utf-8-sig", newline="") as f:  # utf-8-sig: with the byte-order mark
    f.write('"cos_theta","reflectance"\r\n')
    for i in range(rows):
        c = (i + rng.random()) / rows
        f.write(f"{c:+.6f},{0.04 + 0.96 * (1 - c) ** 5 + rng.gauss(0, noise):+.6f}\r\n")
PY

# The noise-free curve on 10,001 points, against which each exported member is measured.
cat > truth.cpp <<'CPP'
#include <cmath>
#include <cstdio>
#include "members.hpp"
int main() {
  for (int k = 0; k < kMembers; ++k) {
    double sum = 0;
    int finite = 0;
    for (int i = 0; i <= 10000; ++i) {
      const double c = i / 10000.0, e = kMember[k](c) - (0.04 + 0.96 * std::pow(1 - c, 5));
      if (std::isfinite(e)) sum += e * e, ++finite;
    }
    std::printf("%d %.6g %d\n", k, std::sqrt(sum / finite), 10001 - finite);  // RMSE where finite, points not
  }
}
CPP

echo "pbrfit held-out rows: $(date -u +%Y-%m-%dT%H:%MZ), $(nproc) cores, $(lscpu | sed -n 's/^Model name: *//p')"
echo "data: $ROWS rows, noise sigma $NOISE, test_fraction 0.3; $GENERATIONS generations, 4 islands of 300, $RANKS ranks"
echo
echo "| seed | front | pick | cost | train RMSE | test RMSE | true RMSE |"
echo "|---|---|---|---|---|---|---|"
: > picks
for ((seed = 1; seed <= SEEDS; seed++)); do
  cat > job.yaml <<YAML
name: heldout
kind: symreg
seed: $seed
output: run.h5
symreg:
  dataset: {csv: data.csv, inputs: [cos_theta], targets: [reflectance], test_fraction: 0.3, sample_seed: $seed}
  operators: [add, sub, mul, div, exp, sqrt]
  constant_probability: 0.4
  islands: 4
  population: 300
  generations: $GENERATIONS
  migration_interval: 10
  migrants: 2
YAML
  rm -f run.h5*
  mpirun "${FLAGS[@]}" -np "$RANKS" "$PBRFIT" run job.yaml > run.log 2>&1 || { cat run.log; exit 1; }
  # The front: row, cost, train and test RMSE, knee flag.
  "$PYTHON" -c '
import h5py
for i, m in enumerate(h5py.File("run.h5", "r")["reflectance/front"][...]):
    print(i, m["cost"], m["rmse"], m["test_rmse"], m["knee"])' > front
  members=$(wc -l < front)
  {
    for ((i = 0; i < members; ++i)); do "$PBRFIT" export run.h5 --member "$i" --format cpp --double --name "m$i"; done
    printf 'constexpr int kMembers = %d;\ndouble (*const kMember[])(double) = {' "$members"
    for ((i = 0; i < members; ++i)); do printf 'm%d, ' "$i"; done
    printf '};\n'
  } > members.hpp
  g++ -std=c++20 -O1 -o truth truth.cpp && ./truth > true_rmse
  # export --member test must pick the row of the lowest test RMSE.
  chosen=$("$PBRFIT" export run.h5 --member test --format cpp --double | sed -n 's/.*member \([0-9]*\) of.*/\1/p')
  join front true_rmse | awk -v seed="$seed" -v members="$members" -v chosen="$chosen" '
    { cost[$1] = $2; train[$1] = $3; test[$1] = $4; truth[$1] = $6; bad[$1] = $7; if ($5 == 1) knee = $1
      if (best_test == "" || $4 < best_test) { best_test = $4; by_test = $1 } }
    END {
      if (by_test != chosen) { print "export --member test chose " chosen ", the lowest test RMSE is row " by_test > "/dev/stderr"; exit 1 }
      n = split("train knee test", name, " "); row["train"] = members - 1; row["knee"] = knee; row["test"] = chosen
      for (k = 1; k <= n; ++k) {
        r = row[name[k]]
        shown = sprintf("%.4f", truth[r]); if (bad[r] > 0) shown = shown sprintf(", not finite at %d point%s", bad[r], (bad[r] > 1 ? "s" : ""))
        printf "| %d | %d | %s (row %d) | %g | %.4f | %.4f | %s |\n", seed, members, name[k], r, cost[r], train[r], test[r], shown
        printf "%s %g %g %d\n", name[k], truth[r], cost[r], bad[r] >> "picks"
      }
    }'
done
echo
echo "Mean over $SEEDS seeds (true RMSE against the noise-free curve; the noise itself is $NOISE):"
echo
echo "| pick | mean cost | mean true RMSE where finite | worst true RMSE | picks not finite somewhere on [0, 1] |"
echo "|---|---|---|---|---|"
awk '{ n[$1]++; cost[$1] += $3; if ($4 > 0) bad[$1]++; sum[$1] += $2; if ($2 > worst[$1]) worst[$1] = $2 }
     END { split("train knee test", order, " ")
           for (k = 1; k <= 3; ++k) { p = order[k]
             printf "| %s | %.1f | %.4f | %.4f | %d of %d |\n", p, cost[p] / n[p], sum[p] / n[p], worst[p], bad[p], n[p] } }' picks
# A pick not finite somewhere is worse than any finite one.
awk '$1 == "train" { train[++a] = ($4 > 0 ? 1e300 : $2) } $1 == "test" { test[++b] = ($4 > 0 ? 1e300 : $2) }
     END { for (i = 1; i <= a; ++i) wins += (test[i] <= train[i])
           printf "\nthe lowest test RMSE at or below the most accurate on training rows, in true RMSE: %d of %d seeds\n", wins, a }' picks
