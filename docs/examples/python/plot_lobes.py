#!/usr/bin/env python3
"""Plots a material's reflection lobes in the plane of incidence, from skinlayer's Python package.

    PYTHONPATH=build/python python3 docs/examples/python/plot_lobes.py --preset skin-fair -o lobes.png

With matplotlib installed (Debian: python3-matplotlib) it writes a polar plot of the cosine-weighted BRDF
f(theta_i, theta_o) cos(theta_o) for light at 0, 30 and 60 degrees, one curve per incidence angle, in the red,
green and blue channels' mean. Without it, it prints the same lobes as CSV (theta_i, theta_o, value).
"""

import argparse
import sys

import numpy as np

import skinlayer


def in_plane_lobes(solution, incidence):
    """theta_o from -89 to 89 degrees (negative: backward, phi 0; positive: forward, phi 180) and the
    cosine-weighted BRDF there, one row per incidence angle."""
    signed = np.linspace(-89.0, 89.0, 179)
    theta_o, phi = np.abs(signed), np.where(signed < 0, 0.0, 180.0)
    brdf = solution.eval(np.asarray(incidence)[:, None], theta_o[None, :], phi[None, :])["brdf"]
    if brdf.ndim == 3:  # a colour material: the channels' mean
        brdf = brdf.mean(axis=-1)
    return signed, brdf * np.cos(np.radians(theta_o))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--preset", default="skin-fair", help="a preset name (default skin-fair)")
    parser.add_argument("-o", "--output", default="lobes.png", help="the plot to write (default lobes.png)")
    arguments = parser.parse_args()

    solution = skinlayer.solve(skinlayer.Material.preset(arguments.preset))
    incidence = [0.0, 30.0, 60.0]
    signed, lobes = in_plane_lobes(solution, incidence)
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("matplotlib is not installed (apt-get install python3-matplotlib); the lobes as CSV:", file=sys.stderr)
        print("theta_i,theta_o,brdf_cos")
        for theta_i, lobe in zip(incidence, lobes):
            for theta_o, value in zip(signed, lobe):
                print(f"{theta_i:g},{theta_o:g},{value:.6g}")
        return
    figure = plt.figure(figsize=(6, 4))
    axes = figure.add_subplot(projection="polar")
    axes.set_theta_zero_location("N")
    axes.set_thetamin(-90)
    axes.set_thetamax(90)
    for theta_i, lobe in zip(incidence, lobes):
        axes.plot(np.radians(signed), lobe, label=f"light at {theta_i:g} deg")
    axes.set_title(f"{arguments.preset}: f cos(theta_o), 1/sr, in the plane of incidence")
    axes.legend(loc="lower left", fontsize="small")
    figure.savefig(arguments.output, dpi=120, bbox_inches="tight")
    print(f"wrote {arguments.output}")


if __name__ == "__main__":
    main()
