#!/usr/bin/env python3
"""The cluster model (docs/BENCHMARKS.md, "Scale past one machine"): what a shipped job would do on 64, 256
and 1,024 ranks, from what was measured here.

Inputs:
  --rate FILE   the table tests/benchmarks/coordinator_rate.sh printed: rank 0's main-thread time per item
                and the stage boundary h(R) at a few rank counts. t0 is the largest time per item measured:
                what rank 0 does per item (build the input, send, receive, fold, write) does not grow with
                the ranks, and its per-round scans over all ranks (dispatch, heartbeats) are per polling
                round, not per item; the measured values vary by about 20 % with no trend. h is extrapolated
                linearly in log2 R (the context goes down a binomial tree), least squares;
  LOG ...       the verbose log (`pbrfit run -v`, stderr) of each job run here; rank 0's lines
                "stage S: N items in W s; computing C ms an item on average, longest L ms" give every
                stage's width N, mean item cost c and longest item l (a stage the run was stopped in:
                its whole width, "(of the stage's M)", at the cost of the items it did).

Per stage at R ranks (one compute thread a rank):
  coordinating  K = N t0(R)                       rank 0's main thread, item by item
  computing     C = max(l, N c / min(R, N))       perfectly balanced: a lower bound
  stage time    T = max(C, K) + h(R)
and over the job: coordinator load = sum K / sum T (the share of rank 0's time spent handing out work),
ranks busy = sum N c / (R sum T) (what the stage widths and the coordinator leave of R ranks), wall = sum T.
The model's T at the measured rank count stands beside the measured stage times, as its check.
"""
import argparse
import math
import re
import sys
from pathlib import Path

STAGE = re.compile(r"\br0\] debug: stage (\d+): (\d+) items in ([0-9.]+) s; computing ([0-9.e+-]+) ms an item on "
                   r"average, longest ([0-9.e+-]+) ms(?: \(of the stage's (\d+)\))?")
RANKS = (64, 256, 1024)


def fit_line(xs, ys):
    n = len(xs)
    if n == 1:
        return 0.0, ys[0]
    mx, my = sum(xs) / n, sum(ys) / n
    sxx = sum((x - mx) ** 2 for x in xs)
    slope = sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sxx if sxx > 0 else 0.0
    return slope, my - slope * mx


def read_rate(path):
    rows = []
    for line in Path(path).read_text().splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) >= 6 and cells[0].isdigit():
            rows.append((int(cells[0]), float(cells[2]) * 1e-6, float(cells[5]) * 1e-3))
    if not rows:
        sys.exit(f"{path}: no table rows of tests/benchmarks/coordinator_rate.sh")
    largest = max(t for _, t, _ in rows)
    h_slope, h_base = fit_line([math.log2(r) for r, _, _ in rows], [h for _, _, h in rows])
    t0 = lambda r: largest
    h = lambda r: max(h_base + h_slope * math.log2(r), min(h for _, _, h in rows))
    return t0, h, rows


def read_stages(path):
    """The stages rank 0 finished, and whether the run was stopped before its end."""
    stages = []
    text = Path(path).read_text(errors="replace")
    for line in text.splitlines():
        m = STAGE.search(line)
        if m:
            # a stage this run did in part (stopped, or resumed within it): its items cost what those done did
            width = int(m[6]) if m[6] else int(m[2])
            stages.append((width, float(m[3]), float(m[4]) * 1e-3, float(m[5]) * 1e-3))
    if not stages:
        sys.exit(f"{path}: no stage lines (run the job with `pbrfit run -v`)")
    return stages, "# stopped at the cap" in text or "(of the stage's" in text


def predict(stages, ranks, t0, h):
    coordinating = computing = total = 0.0
    for n, _, c, longest in stages:
        k = n * t0(ranks)
        t = max(max(longest, n * c / min(ranks, n)), k) + h(ranks)
        coordinating += k
        computing += n * c
        total += t
    return total, coordinating / total, computing / (ranks * total)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rate", required=True)
    parser.add_argument("--measured-ranks", type=int, default=2)
    parser.add_argument("logs", nargs="+")
    args = parser.parse_args()
    t0, h, rows = read_rate(args.rate)
    print("t0 = rank 0's main-thread time per item, h(R) = stage boundary, from " +
          ", ".join(f"R={r}: {1e6 * t:.2f} us, {1e3 * b:.2f} ms" for r, t, b in rows))
    print("extrapolated: " + ", ".join(f"R={r}: {1e6 * t0(r):.2f} us, {1e3 * h(r):.2f} ms" for r in RANKS))
    print()
    head = " | ".join(f"{r} ranks: wall s, busy, rank-0 load" for r in RANKS)
    print(f"| job | stages | items | mean item ms | measured s ({args.measured_ranks} ranks) | model s | {head} |")
    print("|---|---|---|---|---|---|" + "---|" * len(RANKS))
    # The yardstick: a million 1-ms items in one stage (the longest 1.5 ms).
    synthetic = [(1_000_000, 0.0, 1e-3, 1.5e-3)]
    cells = []
    for r in RANKS:
        wall, load, busy = predict(synthetic, r, t0, h)
        cells.append(f"{wall:.3g} s, {100 * busy:.0f} %, {100 * load:.1f} %")
    print(f"| synthetic: 1,000,000 items of 1 ms | 1 | 1000000 | 1 | | {predict(synthetic, args.measured_ranks, t0, h)[0]:.3g} | " +
          " | ".join(cells) + " |")
    for log in args.logs:
        stages, stopped = read_stages(log)
        items = sum(n for n, _, _, _ in stages)
        mean = sum(n * c for n, _, c, _ in stages) / items
        measured = sum(w for _, w, _, _ in stages)
        model, _, _ = predict(stages, args.measured_ranks, t0, h)
        cells = []
        for r in RANKS:
            wall, load, busy = predict(stages, r, t0, h)
            cells.append(f"{wall:.3g} s, {100 * busy:.0f} %, {100 * load:.1f} %")
        name = Path(log).name.removesuffix(".log") + (f" (its first {len(stages)} stages)" if stopped else "")
        shown = f"{measured:.3g}" + (" (stopped)" if stopped else "")
        print(f"| {name} | {len(stages)} | {items} | {1e3 * mean:.3g} | {shown} | {model:.3g} | " +
              " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
