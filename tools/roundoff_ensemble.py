#!/usr/bin/env python3
"""Float against double over the round-off ensemble: paired differences with 95 % intervals.

Reads docs/paper/storage/roundoff/{double,float}_<tag>/timeseries.csv (runs of the paper case
whose fluid density differs in its tenth digit, docs/performance.md) and prints, per measure, each
storage's mean and sample standard deviation, the mean paired difference float - double with its
95 % confidence interval (Student's t), and that interval as a percentage of the double mean.
Usage: tools/roundoff_ensemble.py [FOLDER]
"""
import csv
import math
import os
import sys

# Two-sided 95 % quantiles of Student's t for 1..30 degrees of freedom (any statistics table).
T95 = [12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228, 2.201, 2.179,
       2.160, 2.145, 2.131, 2.120, 2.110, 2.101, 2.093, 2.086, 2.080, 2.074, 2.069, 2.064, 2.060,
       2.056, 2.052, 2.048, 2.045, 2.042]


def rows(path):
    with open(path, newline="") as f:
        return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]


def at(series, tc, column):
    """The value of column in the row nearest t/tau_c = tc."""
    return min(series, key=lambda r: abs(r["t_over_tc"] - tc))[column]


def measures(series):
    peak = max(r["ke_over_ep0"] for r in series if r["t_over_tc"] <= 6.0 + 1e-9)
    return {
        "peak E_k/E_p0 (to 6 tau_c)": peak,
        "Delta L at 3 tau_c": at(series, 3.0, "runout_normalised"),
        "Fr_d at 3 tau_c": at(series, 3.0, "froude_densimetric"),
        "pore pressure at 1 tau_c (Pa)": at(series, 1.0, "pore_pressure_failure_plane_pa"),
        "Delta L at 6 tau_c": at(series, 6.0, "runout_normalised"),
    }


def mean_sd(values):
    m = sum(values) / len(values)
    return m, math.sqrt(sum((v - m) ** 2 for v in values) / (len(values) - 1))


def main():
    folder = sys.argv[1] if len(sys.argv) > 1 else "docs/paper/storage/roundoff"
    tags = sorted(d[len("double_"):] for d in os.listdir(folder) if d.startswith("double_")
                  and os.path.isfile(os.path.join(folder, "float_" + d[len("double_"):],
                                                  "timeseries.csv")))
    runs = {s: [measures(rows(os.path.join(folder, f"{s}_{t}", "timeseries.csv"))) for t in tags]
            for s in ("double", "float")}
    n = len(tags)
    print(f"{n} pairs: {', '.join(tags)}\n")
    print("| quantity | double | float | float - double (paired) | 95 % interval | "
          "interval / double mean | float larger |")
    print("| --- | --- | --- | --- | --- | --- | --- |")
    for name in runs["double"][0]:
        d = [r[name] for r in runs["double"]]
        f = [r[name] for r in runs["float"]]
        diff = [b - a for a, b in zip(d, f)]
        dm, dsd = mean_sd(d)
        fm, fsd = mean_sd(f)
        mm, msd = mean_sd(diff)
        half = T95[n - 2] * msd / math.sqrt(n)
        low, high = mm - half, mm + half
        larger = sum(1 for x in diff if x > 0)
        print(f"| {name} | {dm:.4g} ± {dsd:.2g} | {fm:.4g} ± {fsd:.2g} | {mm:+.3g} | "
              f"[{low:+.3g}, {high:+.3g}] | [{100 * low / abs(dm):+.1f} %, {100 * high / abs(dm):+.1f} %] | "
              f"{larger} of {n} |")


if __name__ == "__main__":
    main()
