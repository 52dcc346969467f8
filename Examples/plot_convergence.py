#!/usr/bin/python3
"""Convergence of Lloyd's method and L-BFGS from the same initial sites (like Rong et al.,
Fig. 8): energy F and |grad F| against energy evaluations and against time, in one PNG.

    /usr/bin/python3 Examples/plot_convergence.py --cvt build/bin/cvt --output convergence.png \
        [--sites 1000] [--resolution 512] [--iterations 100] [--input IMAGE --invert]

Runs `cvt image` twice (same --seed, hence the same initial sites) and reads history.csv.
Needs Debian's python3-matplotlib."""
import argparse
import csv
import os
import subprocess
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")  # no display needed
import matplotlib.pyplot as plt


def run(cvt, method, args, folder):
    command = [cvt, "image", "--method", method, "--sites", str(args.sites),
               "--iterations", str(args.iterations), "--tolerance", "0", "--seed", str(args.seed),
               "--output", folder, "--quiet"]
    if args.input:
        command += ["--input", args.input] + (["--invert"] if args.invert else [])
    else:
        command += ["--resolution", str(args.resolution)]
    subprocess.run(command, check=True)
    with open(os.path.join(folder, "history.csv")) as f:
        rows = list(csv.DictReader(f))
    return {key: [float(row[key]) for row in rows] for key in rows[0]}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cvt", default="build/bin/cvt", help="the cvt program")
    parser.add_argument("--output", default="convergence.png")
    parser.add_argument("--sites", type=int, default=1000)
    parser.add_argument("--resolution", type=int, default=512)
    parser.add_argument("--iterations", type=int, default=100)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--input")
    parser.add_argument("--invert", action="store_true")
    args = parser.parse_args()

    with tempfile.TemporaryDirectory() as folder:
        histories = {method: run(args.cvt, method, args, os.path.join(folder, method))
                     for method in ("lloyd", "lbfgs")}

    figure, axes = plt.subplots(2, 2, figsize=(10, 8))
    labels = {"lloyd": "Lloyd", "lbfgs": "L-BFGS (M = 7)"}
    for method, history in histories.items():
        for row, key in enumerate(("energy", "gradient_norm")):
            axes[row][0].plot(history["evaluations"], history[key], label=labels[method])
            axes[row][1].plot(history["seconds"], history[key], label=labels[method])
    for row, name in enumerate(("energy F", "|grad F|")):
        for column, x in enumerate(("energy evaluations", "seconds")):
            axis = axes[row][column]
            axis.set_yscale("log")
            axis.set_xlabel(x)
            axis.set_ylabel(name)
            axis.grid(True, which="both", alpha=0.3)
            axis.legend()
    figure.suptitle(f"CVT of {args.sites} sites: Lloyd vs L-BFGS (GPU engine)")
    figure.tight_layout()
    figure.savefig(args.output, dpi=100)
    final = {m: h["energy"][-1] for m, h in histories.items()}
    print(f"wrote {args.output}: final energy Lloyd {final['lloyd']:.6g}, "
          f"L-BFGS {final['lbfgs']:.6g}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
