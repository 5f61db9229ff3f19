#!/usr/bin/env python3
"""Frame-time benchmark: shadelab vs the bare OSMesa program in ../shared/bench (probe.cpp).

Both draw the same UV sphere (stacks s, slices 2s) at 1280x720 with the same camera; the machine is
noisy, so the two are run alternately, round after round, and the table reports the median over
rounds of each median frame time, and the median of the per-round ratios shadelab / probe.

  python3 bench/run.py [--shadelab build/shadelab] [--rounds 5] [--frames 60] [--stacks 23,224,708]

Prints a Markdown table (paste it into bench/README.md).
"""
import argparse
import json
import os
import statistics
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
SHARED = os.path.join(os.path.dirname(ROOT), "shared", "bench")
MODES = [("flat", "flatqual"), ("gouraud", "gouraud"), ("phong", "phong")]


def build_probe(out_dir):
    src = os.path.join(SHARED, "probe.cpp")
    exe = os.path.join(out_dir, "probe")
    if not os.path.exists(src):
        sys.exit("bench: %s not found (../shared is absent)" % src)
    if not os.path.exists(exe) or os.path.getmtime(exe) < os.path.getmtime(src):
        os.makedirs(out_dir, exist_ok=True)
        subprocess.check_call(["g++", "-O2", "-std=c++17", "-o", exe, src, "-lOSMesa", "-lpng", "-lstb"])
    return exe


def scene_for(stacks):
    path = os.path.join(HERE, "scenes", "sphere_s%d.json" % stacks)
    if not os.path.exists(path):
        sys.exit("bench: %s missing" % path)
    return path


def run_shadelab(exe, stacks, frames):
    out = subprocess.check_output([exe, scene_for(stacks), "--benchmark", str(frames)], text=True)
    return {j["shading"]: j["median_ms"] for j in map(json.loads, out.splitlines())}


def run_probe(exe, stacks, frames):
    out = subprocess.check_output([exe, "--w", "1280", "--h", "720", "--stacks", str(stacks), "--frames", str(frames),
                                   "--warmup", "3", "--shaders", "flatqual,gouraud,phong", "--quiet"], text=True)
    res = {}
    for line in out.splitlines():
        fields = dict(kv.split("=", 1) for kv in line.split() if "=" in kv)
        res[fields["shader"]] = float(fields["ms_median"])
    return res


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--shadelab", default=os.path.join(ROOT, "build", "shadelab"))
    ap.add_argument("--rounds", type=int, default=5)
    ap.add_argument("--frames", type=int, default=60)
    ap.add_argument("--stacks", default="23,224,708")
    a = ap.parse_args()
    probe = build_probe(os.path.join(ROOT, "build", "bench"))
    print("| triangles (s) | mode | shadelab ms (min-max) | probe ms (min-max) | ratio median (min-max) |")
    print("|---|---|---|---|---|")
    for s in [int(x) for x in a.stacks.split(",")]:
        sl, pr = [], []
        for _ in range(a.rounds):  # alternate, so both see the same machine load
            sl.append(run_shadelab(a.shadelab, s, a.frames))
            pr.append(run_probe(probe, s, a.frames))
        for mode, probe_mode in MODES:
            xs = [r[mode] for r in sl]
            ys = [r[probe_mode] for r in pr]
            ratios = [x / y for x, y in zip(xs, ys)]
            print("| %s (%d) | %s | %.1f (%.1f-%.1f) | %.1f (%.1f-%.1f) | %.2f (%.2f-%.2f) |" % (
                format(4 * s * (s - 1), ","), s, mode, statistics.median(xs), min(xs), max(xs),
                statistics.median(ys), min(ys), max(ys), statistics.median(ratios), min(ratios), max(ratios)))
            sys.stdout.flush()


if __name__ == "__main__":
    main()
