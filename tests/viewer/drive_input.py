#!/usr/bin/env python3
"""Drives the viewer with real X input events (the XTEST extension, through libXtst) and checks what the
keys and the mouse did, from the scene the viewer saves when it is quit with Q.

usage: drive_input.py SHADELAB OUTDIR     (run inside an X server: see xvfb_run.sh)
Exits 77 (skipped) when libX11/libXtst cannot be loaded (Debian: libx11-6, libxtst6); see xinput.py.

Mouse deltas and wheel steps are summed by ImGui
over frames, so the camera's end position does not depend on the frame rate.
"""
import glob, json, math, os, sys

from xinput import quit_viewer, start_viewer

shadelab, out = sys.argv[1], sys.argv[2]
os.makedirs(out, exist_ok=True)
for f in glob.glob(os.path.join(out, "*")):
    os.remove(f)
saved = os.path.join(out, "quit.json")
# 800x600 view + panel on the right; the view's centre is (400, 300) in window and screen coordinates
# (no window manager under Xvfb: the window sits at the origin).
proc, display = start_viewer([shadelab, "--size", "800x600", "--save-scene", saved], out)
key, move, button = display.key, display.move, display.button

move(400, 300, 0.5)
key("2")                  # gouraud, single pane
key("c")                  # compare on ...
key("c")                  # ... and off again
key("w")                  # wireframe (not saved: view state)
key("N", shift=True)      # face normals
key("F12")                # screenshot of the 3D view into the working folder
button(1, True)           # orbit: 100 units right = eye 0.8 rad to its left
for i in range(1, 11):
    move(400 + 10 * i, 300)
button(1, False)
for _ in range(2):        # zoom in two steps: distance * 0.81
    button(4, True)
    button(4, False)
move(1000, 590, 0.3)
button(1, True)           # a drag that starts on the panel moves no camera
for i in range(1, 11):
    move(1000 - 30 * i, 590)
button(1, False)
move(400, 300, 0.3)
button(1, True)           # a click on the sphere sets the pixel probe ...
button(1, False)
key("Escape")             # ... and Esc clears it instead of quitting
key("F12")                # so this second screenshot is taken
quit_viewer(proc, display)

# D twice from compare goes back to compare (issue 31: it went to a single pane).
back = os.path.join(out, "d-twice.json")
proc2, display = start_viewer([shadelab, "--size", "400x300", "--layout", "compare", "--save-scene", back], out)
display.move(200, 150, 0.3)
display.key("d")
display.key("d")
quit_viewer(proc2, display)

failures = []
def check(ok, what):
    if not ok:
        failures.append(what)

layout = json.load(open(back))["layout"] if os.path.exists(back) else None
check(layout == "compare", f"D twice from compare: layout is {layout}")

check(proc.returncode == 0, f"exit status {proc.returncode}")
check(os.path.exists(saved), "no scene saved on quit")
if os.path.exists(saved):
    scene = json.load(open(saved))
    check(scene["shading"] == "gouraud", f"key 2: shading is {scene['shading']}")
    check(scene["layout"] == "single", f"key c twice: layout is {scene['layout']}")
    eye = scene["camera"]["eye"]
    start_dist = math.hypot(1.5, 4.8)  # the default scene's eye (0, 1.5, 4.8), target at the origin
    check(abs(math.dist(eye, [0, 0, 0]) - 0.81 * start_dist) < 0.01, f"wheel: eye distance {math.dist(eye, [0, 0, 0])}")
    yaw = math.atan2(eye[0], eye[2])
    check(abs(yaw + 0.8) < 0.05, f"orbit: yaw {yaw:.3f} rad, expected -0.8 (the panel drag must not orbit)")
    check(abs(eye[1] - 0.81 * 1.5) < 0.01, f"orbit: height {eye[1]:.3f} changed by a horizontal drag")
shots = glob.glob(os.path.join(out, "shadelab-*.png"))
check(len(shots) == 2, f"F12: {len(shots)} screenshots in the working folder (2: Esc with a probe set must not quit)")
if failures:
    sys.exit("; ".join(failures))
print("keys, orbit, zoom, panel capture and F12 work")
