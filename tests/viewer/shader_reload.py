#!/usr/bin/env python3
"""A shader broken on purpose while the viewer runs: F5 shows the driver's error (file and line) and
the picture stays; once the file is fixed, F5 reloads it, and an edit of phong.frag changes the picture.
The Shader view then shows the error's file with its line marked, in whatever layout (issue 31, item 4):
in compare, whose first pane runs flat.vert, and in a single flat pane (phong.frag as one more tab), also
after F5 a second time.

usage: shader_reload.py SHADELAB SHADER_SOURCE_DIR OUTDIR     (inside an X server: see xvfb_run.sh)
"""
import os, shutil, sys, time

from png_rows import read_png
from xinput import quit_viewer, screenshot, start_viewer

shadelab, shader_src, out = sys.argv[1], sys.argv[2], sys.argv[3]
shutil.rmtree(out, ignore_errors=True)
shaders = os.path.join(out, "shaders")
shutil.copytree(shader_src, shaders)
proc, display = start_viewer([shadelab, "--shader-dir", shaders, "--size", "400x300", "--layout", "compare"], out)

first = screenshot(display, out)
phong = os.path.join(shaders, "phong.frag")
good = open(phong).read()
with open(phong, "a") as f:
    f.write("this is not GLSL;\n")
broken_line = good.count("\n") + 1
display.key("F5")                       # reload: must fail and keep the running programs
after_broken = screenshot(display, out)
display.key("2")                        # switching mode must not pick up the broken file either
display.key("c")
after_switch = screenshot(display, out)
open(phong, "w").write(good)
display.key("F5")                       # fixed: reloads
fixed = screenshot(display, out)
# An edit of phong.frag changes the picture: the viewer draws the program its Shader view lists, not
# a speed variant (issue 28). Blue and red swapped in the Phong pane.
edited_source = good.replace("fragmentColor(L)", "fragmentColor(L.bgr)")
open(phong, "w").write(edited_source)
display.key("F5")
edited = screenshot(display, out)
open(phong, "w").write(good)
err = quit_viewer(proc, display)

failures = []
if proc.returncode != 0:
    failures.append(f"exit status {proc.returncode}")
if first is None or after_broken is None or after_switch is None:
    failures.append("F12 wrote no screenshot")
elif not (first == after_broken == after_switch):
    failures.append("the picture changed after a broken shader was reloaded")
if edited_source == good:
    failures.append("phong.frag has no fragmentColor(L) to edit")
elif fixed is None or edited is None or fixed == edited:
    failures.append("an edit of phong.frag did not change the picture after F5")
if "shaders not reloaded" not in err:
    failures.append("no error shown for the broken shader")
if f"phong.frag:{broken_line}" not in err:
    failures.append(f"the error does not point at phong.frag:{broken_line}:\n{err}")


def red_rows(path, left, right):
    """Rows of the window screenshot whose part from `left` to `right` (the Shader view over the 3D
    view) is mostly the listing's red error row (ImGui draws it 150,30,30 at alpha 200), not red text."""
    _, _, rows = read_png(open(path, "rb").read())
    return sum(1 for row in rows
               if sum(1 for r, g, b in row[left:right] if r > 90 and r > 2.5 * max(g, b)) > 0.4 * (right - left))


# The Shader view after a failed F5 (the viewer opens it over the left 60% of the 640-px view): the
# error's line marked in red.
for name, keys in (("compare", ["F5"]), ("compare-F5-twice", ["F5", "F5"]), ("single-flat", ["1", "F5"])):
    window = os.path.join(out, f"window-{name}.png")
    proc, display = start_viewer([shadelab, "--shader-dir", shaders, "--size", "640x480", "--layout", "compare",
                                  "--screenshot", window], out)
    with open(phong, "a") as f:
        f.write("this is not GLSL;\n")
    for key in keys:
        display.key(key)
    time.sleep(2.0)  # the frames after F5: the error's tab selected, then its line scrolled to (a frame each)
    quit_viewer(proc, display)
    open(phong, "w").write(good)
    rows = red_rows(window, 10, 370) if os.path.exists(window) else 0
    if not 12 <= rows <= 120:
        failures.append(f"{name}: the Shader view does not show phong.frag's error line ({rows} red rows over the view)")

if failures:
    sys.exit("; ".join(failures))
print("a broken shader shows its error with file and line, and the picture stays; an edited one changes it;\n"
      "the Shader view shows the error's line in compare and in a single flat pane")
