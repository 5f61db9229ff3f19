#!/usr/bin/env python3
"""shadelab's benchmark: every figure in bench/README.md comes from this script.

  python3 bench/run.py [--shadelab build/shadelab] [--rounds 5] [--frames 40] [--parts frames,compare,process,startup]
                       [--backend auto|osmesa|egl]

frames   shadelab --benchmark vs the bare OSMesa program of ../shared/bench (probe.cpp) on the same UV
         sphere (stacks s, slices 2s) at 1280x720, per mode, for s in --stacks.
compare  the compare layout (three panes) vs the three single-mode frames at a third of the width.
process  whole process, one 1280x720 frame to PNG: shadelab --output vs f3d --output (f3d needs an X
         server: one Xvfb is started for it), wall time and peak memory, spheres made by
         ../shared/bench/gen_sphere.py.
startup  process start to the first frame in the viewer window (Xvfb), default scene: shadelab
         --frames 1, whole process.

The machine is noisy, so the programs run alternately, --rounds times, and the tables give medians
over rounds (min-max) and the median of the per-round ratios. Results also go to
build/bench/results.json for bench/plot.py. --backend is passed to shadelab --benchmark (frames and
compare; the probe is always OSMesa): `--backend egl --parts compare` runs the same benchmark on a GPU
through EGL, and the first line names the renderer shadelab reports.
"""
import argparse
import json
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

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
        subprocess.check_call(["g++", "-O2", "-std=c++17", "-o", exe, src, "-lOSMesa", "-lpng", "-lstb"])
    return exe


def sphere_scene(out_dir, stacks, width=1280, height=720, layout="single"):
    """The probe's sphere, camera, material and light as a scene file."""
    path = os.path.join(out_dir, "sphere_s%d_%dx%d_%s.json" % (stacks, width, height, layout))
    with open(path, "w") as f:
        json.dump({"mesh": {"type": "uvsphere", "slices": 2 * stacks, "stacks": stacks, "radius": 1.0},
                   "material": {"color": [0.2, 0.4, 0.9], "ka": 0.15, "kd": 0.7, "ks": 0.5, "ke": 32},
                   "reflection": "blinn-phong", "layout": layout,
                   "lights": [{"type": "point", "position": [4, 4, 4.862]}],
                   "camera": {"eye": [0, 0, 2.862], "target": [0, 0, 0], "up": [0, 1, 0], "fov_y_deg": 45},
                   "background": [0.2, 0.2, 0.2], "size": [width, height]}, f)
    return path


BACKEND = ["--backend", "auto"]


def shadelab_frames(exe, scene, frames, extra=()):
    out = subprocess.check_output([exe, scene, "--benchmark", str(frames)] + BACKEND + list(extra), text=True)
    return {j["shading"]: j["median_ms"] for j in map(json.loads, out.splitlines())}


def renderer(exe, work):
    """The backend and GL renderer shadelab reports for this machine, e.g. 'osmesa: llvmpipe (...)'."""
    out = subprocess.check_output([exe, sphere_scene(work, 8, 64, 64), "--benchmark", "1", "--shading", "flat"] +
                                  BACKEND, text=True)
    j = json.loads(out.splitlines()[0])
    return "%s: %s" % (j["backend"], j["gl_renderer"])


def probe_frames(exe, stacks, frames):
    out = subprocess.check_output([exe, "--w", "1280", "--h", "720", "--stacks", str(stacks), "--frames", str(frames),
                                   "--warmup", "3", "--shaders", "flatqual,gouraud,phong", "--quiet"], text=True)
    res = {}
    for line in out.splitlines():
        fields = dict(kv.split("=", 1) for kv in line.split() if "=" in kv)
        res[fields["shader"]] = float(fields["ms_median"])
    return res


def row(*cells):
    print("| " + " | ".join(cells) + " |")
    sys.stdout.flush()


def span(xs, fmt="%.1f"):
    return (fmt + " (" + fmt + "-" + fmt + ")") % (statistics.median(xs), min(xs), max(xs))


def part_frames(a, work, probe, results):
    print("\n### Frame time, 1280x720, median ms per frame\n")
    row("triangles (s)", "mode", "shadelab", "probe", "shadelab / probe")
    row("---", "---", "---", "---", "---")
    for s in [int(x) for x in a.stacks.split(",")]:
        scene = sphere_scene(work, s)
        sl, pr = [], []
        for _ in range(a.rounds):
            sl.append(shadelab_frames(a.shadelab, scene, a.frames))
            pr.append(probe_frames(probe, s, a.frames))
        for mode, probe_mode in MODES:
            xs, ys = [r[mode] for r in sl], [r[probe_mode] for r in pr]
            ratios = [x / y for x, y in zip(xs, ys)]
            row("%s (%d)" % (format(4 * s * (s - 1), ","), s), mode, span(xs), span(ys), span(ratios, "%.2f"))
            results.setdefault("frames", []).append({"stacks": s, "triangles": 4 * s * (s - 1), "mode": mode,
                                                     "shadelab_ms": statistics.median(xs),
                                                     "probe_ms": statistics.median(ys),
                                                     "ratio": statistics.median(ratios)})


def part_compare(a, work, results):
    print("\n### Compare layout vs three single-mode frames at a third of the width, median ms\n")
    row("triangles (s)", "compare 1280x720", "flat + gouraud + phong at 427x720", "ratio")
    row("---", "---", "---", "---")
    for s in [int(x) for x in a.stacks.split(",")]:
        compare_scene = sphere_scene(work, s, layout="compare")
        third = sphere_scene(work, s, width=427)
        cs, ss = [], []
        for _ in range(a.rounds):
            cs.append(shadelab_frames(a.shadelab, compare_scene, a.frames)["compare"])
            ss.append(sum(shadelab_frames(a.shadelab, third, a.frames).values()))
        ratios = [c / x for c, x in zip(cs, ss)]
        row("%s (%d)" % (format(4 * s * (s - 1), ","), s), span(cs), span(ss), span(ratios, "%.2f"))
        results.setdefault("compare", []).append({"stacks": s, "compare_ms": statistics.median(cs),
                                                  "sum_ms": statistics.median(ss), "ratio": statistics.median(ratios)})


def timed(cmd, env=None):
    """Wall seconds and peak RSS (MiB) of a command, through GNU time."""
    with tempfile.NamedTemporaryFile("r") as t:
        start = time.monotonic()
        subprocess.run(["/usr/bin/time", "-f", "%M", "-o", t.name] + cmd, check=True, env=env,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        wall = time.monotonic() - start
        return wall, int(t.read().split()[-1]) / 1024.0


class Xvfb:
    def __enter__(self):
        self.proc = subprocess.Popen(["Xvfb", ":97", "-screen", "0", "1920x1080x24", "-nolisten", "tcp"],
                                     stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        time.sleep(1.0)
        self.env = dict(os.environ, DISPLAY=":97")
        return self

    def __exit__(self, *exc):
        self.proc.terminate()
        self.proc.wait()


def part_process(a, work, results):
    f3d = shutil.which("f3d")
    print("\n### Whole process, one 1280x720 frame to PNG: seconds and peak MiB, median (min-max)\n")
    if not f3d:
        print("(f3d not installed: `apt-get install f3d` for the comparison; shadelab only)\n")
    row("file", "shadelab s", "f3d s", "time ratio", "shadelab MiB", "f3d MiB", "memory ratio")
    row("---", "---", "---", "---", "---", "---", "---")
    files = []
    for target, ext in [(2000, "gltf"), (2000, "glb"), (200000, "gltf"), (200000, "glb"), (2000000, "glb"),
                        (2000000, "gltf")]:
        path = os.path.join(work, "sphere_%d.%s" % (target, ext))
        if not os.path.exists(path):
            subprocess.check_call([sys.executable, os.path.join(SHARED, "gen_sphere.py"), "--target", str(target),
                                   "-o", path], stdout=subprocess.DEVNULL)
        files.append(path)
    with Xvfb() as x:
        for path in files:
            out = os.path.join(work, "out.png")
            st, sm, ft, fm = [], [], [], []
            for _ in range(a.rounds):
                w, m = timed([a.shadelab, path, "--size", "1280x720", "--output", out] + BACKEND)
                st.append(w), sm.append(m)
                if f3d:
                    w, m = timed([f3d, "--resolution=1280,720", "--output=" + out, path], env=x.env)
                    ft.append(w), fm.append(m)
            name = os.path.basename(path)
            if f3d:
                row(name, span(st, "%.2f"), span(ft, "%.2f"), span([s / f for s, f in zip(st, ft)], "%.2f"),
                    span(sm, "%.0f"), span(fm, "%.0f"), span([s / f for s, f in zip(sm, fm)], "%.2f"))
            else:
                row(name, span(st, "%.2f"), "-", "-", span(sm, "%.0f"), "-", "-")
            results.setdefault("process", []).append({"file": name, "shadelab_s": statistics.median(st),
                                                      "shadelab_mib": statistics.median(sm),
                                                      "f3d_s": statistics.median(ft) if ft else None,
                                                      "f3d_mib": statistics.median(fm) if fm else None})


def part_startup(a, results):
    print("\n### Start-up: process start to the first frame in the window (Xvfb), default scene\n")
    with Xvfb() as x:
        ts = [timed([a.shadelab, "--frames", "1"], env=x.env)[0] for _ in range(max(a.rounds, 5))]
    row("shadelab --frames 1 (whole process, window + panel + first frame + exit)", span(ts, "%.3f") + " s")
    results["startup_s"] = statistics.median(ts)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--shadelab", default=os.path.join(ROOT, "build", "shadelab"))
    ap.add_argument("--rounds", type=int, default=5)
    ap.add_argument("--frames", type=int, default=40)
    ap.add_argument("--stacks", default="23,224,708")
    ap.add_argument("--parts", default="frames,compare,process,startup")
    ap.add_argument("--backend", default="auto", choices=["auto", "osmesa", "egl"])
    a = ap.parse_args()
    BACKEND[1] = a.backend
    work = os.path.join(ROOT, "build", "bench")
    os.makedirs(work, exist_ok=True)
    results = {}
    parts = a.parts.split(",")
    print("Machine: %d cores, %s; shadelab renders with %s" % (
        os.cpu_count(), subprocess.check_output(["uname", "-sr"], text=True).strip(), renderer(a.shadelab, work)))
    if "frames" in parts:
        part_frames(a, work, build_probe(work), results)
    if "compare" in parts:
        part_compare(a, work, results)
    if "process" in parts:
        part_process(a, work, results)
    if "startup" in parts:
        part_startup(a, results)
    with open(os.path.join(work, "results.json"), "w") as f:
        json.dump(results, f, indent=1)


if __name__ == "__main__":
    main()
