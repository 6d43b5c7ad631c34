"""Times `Solution.eval` over 10^6 random direction pairs from Python (issue 27's target: under 1 s on 2 cores).

bench_core's BM_EvalPairs times the C++ function underneath; this adds what Python costs on top: turning the numpy
arrays into spans and the results into a dict of arrays. Run it with `cmake --build build --target bench-python`,
or as PYTHONPATH=build/python python3 tests/bench/bench_python_eval.py [--repetitions N].
"""

import argparse
import os
import statistics
import time

import numpy as np

import skinlayer

PAIRS = 1_000_000


def materials():
    """(name, material) for the issue's RGB example, the grey default and a spectral skin."""
    return [
        ("RGB layer over a matched bottom (the issue's example)",
         skinlayer.Material(sigma=0.3, T=0.5, albedo=(0.9, 0.7, 0.5), bottom="matched")),
        ("grey default, two rough interfaces", skinlayer.Material()),
        ("skin-medium (spectral, weighed into RGB)", skinlayer.Material.preset("skin-medium")),
    ]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repetitions", type=int, default=5, help="timed calls per material (default 5)")
    repetitions = parser.parse_args().repetitions
    if repetitions < 1:
        parser.error(f"--repetitions = {repetitions} is out of range; valid range is [1, inf)")
    random = np.random.default_rng(27)
    theta_i, theta_o = random.uniform(0.0, 90.0, PAIRS), random.uniform(0.0, 90.0, PAIRS)
    phi = random.uniform(0.0, 360.0, PAIRS)
    print(f"Solution.eval over {PAIRS} random pairs, {os.cpu_count()} cores; ms per call")
    print("| material | first call | median of the next | range |\n|---|---|---|---|")
    for name, material in materials():
        solution = skinlayer.solve(material)
        times = []
        for _ in range(repetitions + 1):
            start = time.perf_counter()
            solution.eval(theta_i, theta_o, phi)
            times.append(1e3 * (time.perf_counter() - start))
        rest = times[1:]
        print(f"| {name} | {times[0]:.0f} | {statistics.median(rest):.0f} | {min(rest):.0f}-{max(rest):.0f} |",
              flush=True)


if __name__ == "__main__":
    main()
