#!/usr/bin/env python3
"""Steps the viewer through a playlist with real X key events (XTEST, see xinput.py) and checks, from F12
screenshots of the 3D view and the scene saved on quit, that Page Down / Page Up and the arrow keys
move between presets, that a preset keeps its live edits while the lecturer steps away and back, and
that Backspace (reset preset) brings back the preset as its file has it.

usage: drive_playlist.py SHADELAB PLAYLIST_DIR OUTDIR      (inside an X server: see xvfb_run.sh)
       drive_playlist.py --walk SHADELAB PLAYLIST_DIR OUTDIR
--walk pages through every preset of the folder once (the lecture's playlist) and checks that each was
shown, in order, without an error.
"""
import glob, json, os, sys

from xinput import quit_viewer, screenshot, start_viewer

walk = sys.argv[1] == "--walk"
shadelab, playlist, out = sys.argv[1 + walk:4 + walk]
os.makedirs(out, exist_ok=True)
for f in glob.glob(os.path.join(out, "*")):
    os.remove(f)
saved = os.path.join(out, "quit.json")
size = "320x180" if walk else "400x300"
proc, display = start_viewer([shadelab, "--playlist", playlist, "--size", size, "--save-scene", saved], out)
failures = []


def check(ok, what):
    if not ok:
        failures.append(what)


def finish():
    err = quit_viewer(proc, display)
    check(proc.returncode == 0, f"exit status {proc.returncode}")
    return err


def shot():
    image = screenshot(display, out)
    check(image is not None, "F12 wrote no screenshot")
    return image


if walk:
    presets = sorted(f for f in os.listdir(playlist) if f.endswith(".json") and not f.startswith("."))
    display.move(100, 100, 0.2)
    for _ in range(len(presets)):  # one more than needed: at the last preset Page Down stays there
        display.key("Next", hold=0.1, after=0.15)  # a 320x180 preset draws in well under 0.25 s
    err = finish()
    for k, name in enumerate(presets[1:], start=2):
        check(f"preset {k}/{len(presets)}: {os.path.join(playlist, name)}" in err, f"preset {k} ({name}) was not shown")
    check(f"preset {len(presets) + 1}/" not in err, "stepped past the last preset")
    errors = [line for line in err.splitlines() if line.startswith("shadelab: ") and "preset " not in line
              and "viewer on" not in line and "wrote" not in line and " frames, median " not in line]
    check(not errors, "errors while stepping: " + "; ".join(errors))
    if os.path.exists(saved):
        title = json.load(open(saved)).get("title")
        expected = json.load(open(os.path.join(playlist, presets[-1]))).get("title")
        check(title == expected, f"ended on \"{title}\", expected the last preset \"{expected}\"")
    else:
        failures.append("no scene saved on quit")
    if failures:
        sys.exit("; ".join(failures))
    print(f"paged through all {len(presets)} presets")
    sys.exit(0)

display.move(200, 150, 0.2)  # over the 3D view, away from the panel
first = shot()                 # preset 1
display.key("Next")                  # Page Down: preset 2
second = shot()
display.key("1")                     # a live edit: flat shading
second_edited = shot()
display.key("Right")                 # preset 3
third = shot()
display.key("Left")                  # back to preset 2: the edit is still there
second_again = shot()
display.key("BackSpace")             # reset preset 2 from its file
second_reset = shot()
display.key("Prior")                 # Page Up: preset 1
first_again = shot()
display.key("End")                   # the last preset ...
display.key("Home")                  # ... and the first again
err = finish()

check(first != second, "Page Down did not change the picture")
check(second != second_edited, "key 1 did not change preset 2")
check(third not in (second, second_edited), "Right did not move to preset 3")
check(second_again == second_edited, "preset 2 lost its edit when stepping away and back")
check(second_reset == second, "Backspace did not restore preset 2 as its file has it")
check(first_again == first, "Page Up did not return to preset 1 as it was")
for line in ("preset 2/3", "preset 3/3", "reset preset 2", "preset 1/3"):
    check(line in err, f"no \"{line}\" in the log")
check(err.count("preset 3/3") == 2, "End did not move to preset 3")
if os.path.exists(saved):
    scene = json.load(open(saved))
    check(scene.get("title") == "First preset", f"Home: quit on \"{scene.get('title')}\", expected the first preset")
else:
    failures.append("no scene saved on quit")
if failures:
    sys.exit("; ".join(failures))
print("Page Down/Up, arrows, Home/End step the playlist; edits stay with their preset; Backspace resets it")
