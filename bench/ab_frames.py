#!/usr/bin/env python3
"""Two builds' frame times, alternating: `--benchmark 20` (the median ms of 20 frames) of OLD then NEW on
each scene, ROUNDS times, so both see the same load; prints the medians and the per-round ratios NEW/OLD.

    /usr/bin/python3 bench/ab_frames.py OLD/shadelab NEW/shadelab [ROUNDS] [--lights]

--lights adds presets 17 (shadow maps per light) and 20 (a 4x4-sampled area light).
"""
import json
import os
import statistics
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
LECTURE = os.path.join(HERE, "..", "assets", "scenes", "lecture")
SCENES = [("200k-triangle sphere", ["--mesh", "uvsphere:224:224"]),
          ("01 compare", [os.path.join(LECTURE, "01-flat-gouraud-phong.json")]),
          ("16 occlusion", [os.path.join(LECTURE, "16-occlusion.json")])]
# With --lights: also the presets whose frames are mostly shadow maps and area-light samples.
LIGHTS = [("17 shadows per light", [os.path.join(LECTURE, "17-occlusion-per-light.json")]),
          ("20 area light 4x4", [os.path.join(LECTURE, "20-area-light-4x4.json")])]


def run(binary, args):
    out = subprocess.run([binary] + args + ["--benchmark", "20"], capture_output=True, text=True, check=True).stdout
    rows = [json.loads(line) for line in out.splitlines() if line.startswith("{")]
    return {r["shading"] if r["layout"] == "single" else r["layout"]: r["median_ms"] for r in rows}


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    lights = "--lights" in sys.argv
    argv = [a for a in sys.argv if a != "--lights"]
    old, new = argv[1], argv[2]
    rounds = int(argv[3]) if len(argv) > 3 else 5
    res = {}
    for _ in range(rounds):
        for name, args in SCENES + (LIGHTS if lights else []):
            a, b = run(old, args), run(new, args)
            for mode in a:
                res.setdefault((name, mode), []).append((a[mode], b[mode]))
    print("| scene | mode | old, median ms | new, median ms | new / old, median of rounds (min-max) |")
    print("|---|---|---|---|---|")
    for (name, mode), v in res.items():
        ratios = [y / x for x, y in v]
        print("| %s | %s | %.1f | %.1f | %.2f (%.2f-%.2f) |" % (name, mode, statistics.median(x for x, _ in v),
              statistics.median(y for _, y in v), statistics.median(ratios), min(ratios), max(ratios)))


if __name__ == "__main__":
    main()
