#!/usr/bin/env python3
"""A folder of 100 screenshot tests for `shadelab --test` (issue 19's speed target: 100 scenes at
320x240 in at most 10 s on the 2-core machine, one process).

  python3 bench/test_folder.py [--out build/bench/test100] [--shadelab build/shadelab]

writes OUT/NN-NAME.json, 100 scenes at 320x240: the lecture presets (assets/scenes/lecture) and the
shadow scenes (assets/scenes), then variations of the default scene (k_e, shading mode, layout,
reflection model, the light moved, a second light) until there are 100; then runs
`shadelab --test OUT --update` once so every scene has its reference OUT/NN-NAME.png. Time the run
itself with (bench/README.md, "A folder of screenshot tests"):

  /usr/bin/time -v build/shadelab --test build/bench/test100
"""
import argparse
import itertools
import json
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SIZE = [320, 240]
COUNT = 100


def load(path):
    with open(path) as f:
        return json.load(f)


def presets():
    """The lecture presets and the shadow scenes, as they are, at 320x240."""
    lecture = os.path.join(ROOT, "assets", "scenes", "lecture")
    files = [os.path.join(lecture, n) for n in sorted(os.listdir(lecture)) if n.endswith(".json")]
    scenes = os.path.join(ROOT, "assets", "scenes")
    files += [os.path.join(scenes, n) for n in sorted(os.listdir(scenes)) if n.startswith("shadow_")]
    for path in files:
        scene = load(path)
        scene["size"] = SIZE
        yield os.path.splitext(os.path.basename(path))[0], scene


def variations():
    """The default scene with one or two things changed, in a fixed order."""
    base = load(os.path.join(ROOT, "assets", "scenes", "default.json"))
    base["size"] = SIZE
    kes = [1, 4, 8, 16, 32, 64, 128, 512]
    modes = ["flat", "gouraud", "phong"]
    reflections = ["phong", "blinn-phong"]
    lights = [[3, 4, 5], [-3, 4, 5], [0, 5, 2]]
    for light, reflection, mode, ke in itertools.product(lights, reflections, modes, kes):
        scene = json.loads(json.dumps(base))
        scene["material"]["ke"] = ke
        scene["shading"] = mode
        scene["reflection"] = reflection
        scene["lights"][0]["position"] = light
        yield f"default-ke{ke}-{mode}-{reflection}-light{light[0]}{light[1]}{light[2]}", scene
        if ke == 32 and light == lights[0]:  # the compare layout and a second light, now and then
            compare = json.loads(json.dumps(scene))
            compare["layout"] = "compare"
            yield f"default-ke{ke}-compare-{reflection}-from-{mode}", compare
            two = json.loads(json.dumps(scene))
            two["lights"].append({"type": "point", "position": [-4, 2, 3], "color": [0.4, 0.5, 1.0]})
            yield f"default-ke{ke}-{mode}-{reflection}-two-lights", two


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", default=os.path.join(ROOT, "build", "bench", "test100"))
    parser.add_argument("--shadelab", default=os.path.join(ROOT, "build", "shadelab"))
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    for name in os.listdir(args.out):
        if name.endswith((".json", ".png")):
            os.remove(os.path.join(args.out, name))
    for n, (name, scene) in enumerate(itertools.islice(itertools.chain(presets(), variations()), COUNT)):
        with open(os.path.join(args.out, f"{n:03d}-{name}.json"), "w") as f:
            json.dump(scene, f, indent=1)
    # The references: this build's renders (the speed is measured, not the pixels).
    run = subprocess.run([args.shadelab, "--test", args.out, "--update"], capture_output=True, text=True)
    print(run.stdout.splitlines()[-1] if run.stdout else run.stderr.strip())
    return run.returncode


if __name__ == "__main__":
    sys.exit(main())
