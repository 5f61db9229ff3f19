#!/usr/bin/python3
"""Plots frame time against triangle count for the three shading modes, shadelab and the bare OSMesa
reference on the same axes, from build/bench/results.json (written by bench/run.py).

  bench/plot.py [results.json] [-o bench/frame_time.png]   (Debian's /usr/bin/python3 with python3-matplotlib)
"""
import argparse
import json
import os

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("results", nargs="?", default=os.path.join(ROOT, "build", "bench", "results.json"))
    ap.add_argument("-o", "--output", default=os.path.join(HERE, "frame_time.png"))
    a = ap.parse_args()
    rows = json.load(open(a.results))["frames"]
    colours = {"flat": "#d95f02", "gouraud": "#1b9e77", "phong": "#7570b3"}
    fig, ax = plt.subplots(figsize=(7.5, 4.8), dpi=110)
    for mode, colour in colours.items():
        pts = sorted((r["triangles"], r["shadelab_ms"], r["probe_ms"]) for r in rows if r["mode"] == mode)
        tris = [p[0] for p in pts]
        ax.plot(tris, [p[1] for p in pts], "-o", color=colour, label="shadelab " + mode)
        ax.plot(tris, [p[2] for p in pts], "--s", color=colour, alpha=0.6,
                label="reference " + ("flat (flat qualifier)" if mode == "flat" else mode))
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("triangles (UV sphere, 1280x720, llvmpipe, 2 cores)")
    ax.set_ylabel("median ms per frame")
    ax.set_title("Frame time: shadelab vs the bare OSMesa program (../shared/bench)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8, ncol=2)
    fig.tight_layout()
    fig.savefig(a.output)
    print("wrote", a.output)


if __name__ == "__main__":
    main()
