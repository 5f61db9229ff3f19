#!/usr/bin/env python3
"""Frame time while a lecturer drags (issue 31, item 12): for each lecture preset given, the viewer is
opened on it, resized to 1920x1080 (panel shown), the view is orbit-dragged for 4 s with real X input
(XTEST), and the viewer's -v median frame time and frame count are printed (the drag's frames are most
of the run's). Run inside an X server with xdotool, e.g.

  xvfb-run -a -s "-screen 0 1920x1080x24" python3 bench/drag_frames.py build/shadelab assets 1,15,16,17,20,21

usage: drag_frames.py SHADELAB ASSETS PRESET_NUMBERS
"""
import math, os, re, subprocess, sys, time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "viewer"))
from xinput import quit_viewer, start_viewer  # noqa: E402

shadelab, assets, numbers = os.path.abspath(sys.argv[1]), sys.argv[2], sys.argv[3]
folder = os.path.join(assets, "scenes", "lecture")
files = sorted(f for f in os.listdir(folder) if f.endswith(".json"))
for number in (int(n) for n in numbers.split(",")):
    proc, display = start_viewer([shadelab, os.path.join(folder, files[number - 1])], os.getcwd())
    window = subprocess.run(["xdotool", "search", "--name", "^shadelab$"], capture_output=True, text=True).stdout.split()[0]
    subprocess.run(["xdotool", "windowsize", window, "1920", "1080"], check=True)
    time.sleep(2.5)  # start-up and the first still (anti-aliased) frames
    display.move(700, 600, 0.5)
    display.button(1, True)
    start, step = time.monotonic(), 0
    while time.monotonic() - start < 4.0:
        step += 1
        display.move(int(700 + 150 * math.sin(step * 0.05)), int(600 + 40 * math.cos(step * 0.05)), 0.01)
    display.button(1, False)
    time.sleep(1.0)
    found = re.search(r"(\d+) frames, median ([0-9.]+) ms", quit_viewer(proc, display))
    print(f"{files[number - 1]}: {found.group(1)} frames, median {float(found.group(2)):.1f} ms", flush=True)
