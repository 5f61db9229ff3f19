#!/usr/bin/env python3
"""Drives the viewer with real X input events (the XTEST extension, through libXtst) and checks what the
keys and the mouse did, from the scene the viewer saves when it is quit with Q.

usage: drive_input.py SHADELAB OUTDIR     (run inside an X server: see xvfb_run.sh)
Exits 77 (skipped) when libX11/libXtst cannot be loaded (Debian: libx11-6, libxtst6); see xinput.py.

Mouse deltas and wheel steps are summed by ImGui
over frames, so the camera's end position does not depend on the frame rate.
"""
import glob, json, math, os, sys, time

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


def scroll_grab_top():
    """The panel's scrollbar grab: its top row on the screen (ImGui's grey in the window's last columns)."""
    width, height, rows = display.grab(868, 24, 12, 300)
    ys = [y for y in range(height) if sum(1 for p in rows[y] if 70 <= p[0] <= 140 and abs(p[0] - p[2]) <= 8) >= 3]
    return ys[0] if ys else None


def message_pixels():
    """White text in the band at the view's bottom, where the status message is drawn."""
    _, _, rows = display.grab(20, 24 + 300 - 70, 360, 70)
    return sum(1 for row in rows for p in row if min(p) > 240)


# The probe and the panel (issue 31, item 11): a click on the view scrolls a scrolled panel to the Probe
# section (its first: the grab back at the top); R (the camera reset) takes the "probe at pixel" message away.
display.move(600, 200, 0.3)
for _ in range(8):  # wheel steps over the panel (ImGui sums them over frames)
    display.button(5, True, 0.02)
    display.button(5, False, 0.02)
time.sleep(0.4)
scrolled = scroll_grab_top()
display.move(200, 24 + 150, 0.1)  # the middle pane's sphere
display.button(1, True)
display.button(1, False)
time.sleep(0.4)
probed, message = scroll_grab_top(), message_pixels()
display.key("r", after=0.2)
after_reset = message_pixels()
quit_viewer(proc2, display)

failures = []
def check(ok, what):
    if not ok:
        failures.append(what)

print(f"panel scrollbar grab at row {scrolled} scrolled, {probed} after the probe; message {message} white pixels, "
      f"{after_reset} after R")
check(scrolled is not None and probed is not None and scrolled > probed + 20 and probed < 12,
      f"the panel did not scroll to the Probe section: its grab at row {scrolled}, then {probed}")
check(message > 50 and after_reset < 5, f"R with a probe set: the message's {message} white pixels, {after_reset} after R")
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
