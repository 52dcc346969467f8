#!/usr/bin/python3
"""How the engines scale: milliseconds per Lloyd iteration against pixels (1000 sites) and
against sites (at the largest image), with the resident memory each run added, in one PNG.

    /usr/bin/python3 Examples/plot_scaling.py --benchmark build/bin/cvtBenchmark \
        --output scaling.png [--max-side 4096] [--max-sites 100000] [--save scaling.csv]
    /usr/bin/python3 Examples/plot_scaling.py --csv scaling.csv --output scaling.png

Runs `cvtBenchmark scaling` (or reads its saved output) and draws both engines.
Needs Debian's python3-matplotlib."""
import argparse
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")  # no display needed
import matplotlib.pyplot as plt


def read(lines):
    rows = []
    for line in lines:
        fields = line.strip().split(",")
        if len(fields) == 7 and fields[0] == "scaling" and fields[1] != "engine":
            rows.append({"engine": fields[1], "side": int(fields[2]), "sites": int(fields[3]),
                         "ms": float(fields[4]), "mib": float(fields[5])})
    return rows


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--benchmark", default="build/bin/cvtBenchmark")
    parser.add_argument("--csv", help="read a saved `cvtBenchmark scaling` output instead")
    parser.add_argument("--save", help="also save the benchmark's output here")
    parser.add_argument("--max-side", type=int, default=4096)
    parser.add_argument("--max-sites", type=int, default=100000)
    parser.add_argument("--output", default="scaling.png")
    args = parser.parse_args()
    if args.csv:
        with open(args.csv) as f:
            text = f.read()
    else:
        text = subprocess.run([args.benchmark, "scaling", str(args.max_side), str(args.max_sites)],
                              check=True, capture_output=True, text=True).stdout
        if args.save:
            with open(args.save, "w") as f:
                f.write(text)
    rows = read(text.splitlines())
    if not rows:
        sys.exit("no scaling lines in the benchmark's output")
    largest = max(r["side"] for r in rows)
    figure, (by_pixels, by_sites) = plt.subplots(1, 2, figsize=(11, 4.5))
    for engine, style in (("CPU", "o-"), ("OpenGL", "s--")):
        pixels = sorted((r for r in rows if r["engine"] == engine and r["sites"] <= 1000),
                        key=lambda r: r["side"])
        sites = sorted((r for r in rows if r["engine"] == engine and r["side"] == largest),
                       key=lambda r: r["sites"])
        for axis, points, key in ((by_pixels, pixels, "side"), (by_sites, sites, "sites")):
            if not points:
                continue
            x = [p[key] ** 2 if key == "side" else p[key] for p in points]
            axis.plot(x, [p["ms"] for p in points], style, label=engine)
            for xi, p in zip(x, points):
                axis.annotate("%.0f MiB" % p["mib"], (xi, p["ms"]), textcoords="offset points",
                              xytext=(4, 4), fontsize=7)
    by_pixels.set(xscale="log", yscale="log", xlabel="pixels (1000 sites)",
                  ylabel="ms per Lloyd iteration", title="against image size")
    by_sites.set(xscale="log", yscale="log", xlabel="sites (%d x %d pixels)" % (largest, largest),
                 ylabel="ms per Lloyd iteration", title="against site count")
    for axis in (by_pixels, by_sites):
        axis.grid(True, which="both", alpha=0.3)
        axis.legend()
    figure.suptitle("CVT engines on this machine (labels: resident memory of the run)")
    figure.tight_layout()
    figure.savefig(args.output, dpi=100)
    print("wrote %s (%d measurements)" % (args.output, len(rows)))


if __name__ == "__main__":
    main()
