#!/usr/bin/env python3
"""The viewer as a lecturer uses it, with real X input (XTEST) and window resizes (xdotool):

  framing   resized to the whole screen, and switched between layouts: every pane shows the whole model
            (no pane border touches it)
  zoom      each wheel step in makes the model larger and each step out smaller, also after F
  idle      with nothing happening the viewer sleeps: CPU time over 4 s stays under 2% of a core
  help      F1 puts every key over the view; Esc takes it away; Esc never quits, Q does
  lightdrag dragging a light's marker moves the light in the plane facing the camera, and the highlight
            with it (not the camera)
  textfield a click on the path field, then a click on the view (or Esc) gives the keyboard back to
            the shortcuts (2, 3, q)
  remember  window size and UI scale come back in the next session; --reset-layout forgets them
  hidpi     at a 2x content scale (Xft.dpi 192) the view keeps half the window and the panes show the
            whole model
  labels    at 1920x1080, at UI scale 1 and 1.5: the light labels keep off the spheres in compare (the
            window's view differs from F12's image on under 0.3% of a model's pixels: markers, not labels);
            in a 1200x800 window with E's formula on the k_e sphere: the formula covers none of it
  viewtext  at 1920x1080 with the panel at UI scale 0.8: the caption's lines are at least 3% of the window's
            height; a playing k_e ramp shows a large live readout of k_e
  shaderview at 1920x1080, S: the shader's lines over the view are at least 2% of the window's height
            tall (a term line's bar) and the wrapped code reaches across the box
  animcap   a playing --animate draws at most 60 frames a second (the display's refresh), counted by -v
  slides    at 1920x1080: the k_e series 04-08 (one caption wraps to two lines) has the very same view
            rectangle and sphere on every slide; compare panes leave a margin (at least 6% of the pane's
            width each side) and a separator line is drawn between them in the window, not in F12's image;
            a slide change puts no message over the view (the window's view equals a fresh session's)

usage: lecture_hall.py SCENARIO SHADELAB ASSETS OUTDIR   (inside an X server: see xvfb_run.sh)
Exits 77 (skipped) where libXtst or xdotool is missing. The screenshots stay in OUTDIR to be looked at.
"""
import os, shutil, subprocess, sys, time

from png_rows import read_png
from xinput import quit_viewer, screenshot, start_viewer

scenario, shadelab, assets, out = sys.argv[1:5]
if not shutil.which("xdotool"):
    print("xdotool not found (Debian: xdotool): skipping")
    sys.exit(77)
shutil.rmtree(out, ignore_errors=True)
os.makedirs(out)
failures = []


def check(ok, what):
    if not ok:
        failures.append(what)


def shot(name):
    data = screenshot(display, out)
    if data is None:
        failures.append(f"{name}: F12 wrote no screenshot")
        return None
    open(os.path.join(out, name + ".png"), "wb").write(data)
    return read_png(data)


def panes(image, count):
    """Each pane's (x0, x1) of a view `count` panes wide (compare: three equal panes)."""
    width = image[0]
    return [(i * (width // count), (i + 1) * (width // count)) for i in range(count)]


def touches_border(image, x0, x1):
    """True when the model reaches a pane border: a border pixel differs from the background (a corner)."""
    width, height, rows = image
    background = rows[height - 1][x0]
    for y in range(height):
        for x in (x0, x0 + 1, x1 - 2, x1 - 1):
            if max(abs(a - b) for a, b in zip(rows[y][x], background)) > 6:
                return True
    for x in range(x0, x1):
        for y in (0, 1, height - 2, height - 1):
            if max(abs(a - b) for a, b in zip(rows[y][x], background)) > 6:
                return True
    return False


def model_pixels(image, x0, x1):
    width, height, rows = image
    background = rows[height - 1][x0]
    return sum(1 for y in range(0, height, 2) for x in range(x0, x1, 2)
               if max(abs(a - b) for a, b in zip(rows[y][x], background)) > 6)


def model_box(image, x0=0, x1=None):
    """(left, top, right, bottom) of what differs from the background in x0..x1, or None."""
    width, height, rows = image
    x1 = width if x1 is None else x1
    background = rows[height - 1][x0]
    xs, ys = [], []
    for y in range(height):
        row = rows[y]
        hits = [x for x in range(x0, x1) if max(abs(a - b) for a, b in zip(row[x], background)) > 6]
        if hits:
            xs += (hits[0], hits[-1])
            ys.append(y)
    return (min(xs), min(ys), max(xs), max(ys)) if xs else None


def window_id():
    return subprocess.run(["xdotool", "search", "--name", "^shadelab$"], capture_output=True, text=True).stdout.split()[0]


def resize(width, height):
    subprocess.run(["xdotool", "windowsize", window_id(), str(width), str(height)], check=True)
    time.sleep(1.0)


def wheel(button, steps):
    for _ in range(steps):
        display.button(button, True)
        display.button(button, False)
    time.sleep(0.5)


playlist = os.path.join(assets, "scenes", "lecture")
if scenario == "framing":
    proc, display = start_viewer([shadelab, "--playlist", playlist], out)
    display.move(300, 500, 0.5)
    resize(1920, 1080)  # as if maximised on a 1920x1080 projector
    for preset in range(3):  # compare, compare with 16,000 triangles, the diff layout
        image = shot(f"preset{preset + 1}-1920x1080")
        if image:
            for x0, x1 in panes(image, 3):
                check(not touches_border(image, x0, x1), f"preset {preset + 1} at 1920x1080: the model touches a border of pane {x0}..{x1}")
        display.key("Next")
    display.key("Home")
    display.key("Tab")  # the panel hidden: wider panes
    image = shot("panel-hidden")
    if image:
        for x0, x1 in panes(image, 3):
            check(not touches_border(image, x0, x1), f"panel hidden: the model touches pane {x0}..{x1}")
    display.key("Tab")
    resize(900, 500)
    image = shot("900x500")
    if image:
        for x0, x1 in panes(image, 3):
            check(not touches_border(image, x0, x1), f"900x500: the model touches pane {x0}..{x1}")
    display.key("1")  # single layout
    image = shot("single")
    if image:
        check(not touches_border(image, 0, image[0]), "single layout: the model touches the border")
    quit_viewer(proc, display)
elif scenario == "zoom":
    proc, display = start_viewer([shadelab, "--size", "800x600", "--mesh", "icosphere:3"], out)
    display.move(400, 330, 0.5)
    for when in ("start", "after F"):
        if when == "after F":
            display.key("f")
        sizes = [model_pixels(shot(f"{when}-0"), 0, 800)]
        for step in range(1, 4):
            wheel(4, 1)  # wheel up: in
            sizes.append(model_pixels(shot(f"{when}-in{step}"), 0, 800))
        for step in range(1, 7):
            wheel(5, 1)  # wheel down: out
            sizes.append(model_pixels(shot(f"{when}-out{step}"), 0, 800))
        ins, outs = sizes[:4], sizes[3:]
        check(all(b > a for a, b in zip(ins, ins[1:])), f"{when}: wheel in does not grow the model: {ins}")
        check(all(b < a for a, b in zip(outs, outs[1:])), f"{when}: wheel out does not shrink the model: {outs}")
    quit_viewer(proc, display)
elif scenario == "idle":
    proc, display = start_viewer([shadelab, "--playlist", playlist], out)
    def cpu_seconds():
        fields = open(f"/proc/{proc.pid}/stat").read().rsplit(")", 1)[1].split()
        return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")  # utime + stime
    # Start-up (shader builds, the first frames, the anti-aliased still frame) may take a while on a
    # loaded machine: wait until a second passes with almost no CPU, 20 s at most, then measure.
    for _ in range(20):
        before = cpu_seconds()
        time.sleep(1.0)
        if cpu_seconds() - before < 0.01:
            break
    before, start = cpu_seconds(), time.monotonic()
    time.sleep(4.0)
    share = (cpu_seconds() - before) / (time.monotonic() - start)
    print(f"idle: {100 * share:.2f}% of a core")
    check(share <= 0.02, f"idle: {100 * share:.1f}% of a core (at most 2%)")
    display.key("Next")  # an input draws at once
    check(proc.poll() is None, "the viewer ended")
    quit_viewer(proc, display)
elif scenario == "help":
    window = os.path.join(out, "help-window.png")
    proc, display = start_viewer([shadelab, "--size", "900x600", "--screenshot", window], out)
    display.move(450, 330, 0.5)
    display.key("F1")
    display.key("Escape")  # closes the help ...
    display.key("Escape")  # ... and a second Esc does not quit
    check(proc.poll() is None, "Esc quit the viewer")
    display.key("F1")      # open again for the screenshot taken on quitting
    quit_viewer(proc, display)
    _, height, rows = read_png(open(window, "rb").read())
    # The help box over the view's centre: light text on a dark box, many rows of it.
    light_rows = sum(1 for y in range(100, height - 100) if sum(1 for x in range(150, 750) if min(rows[y][x]) > 190) > 3)
    check(light_rows > 150, f"F1: {light_rows} rows of text over the view")
elif scenario == "hidpi":
    if not shutil.which("xrdb"):
        print("xrdb not found (Debian: x11-xserver-utils): skipping")
        sys.exit(77)
    subprocess.run(["xrdb", "-nocpp", "-merge"], input="Xft.dpi: 192\n", text=True, check=True)
    proc, display = start_viewer([shadelab, "--playlist", playlist], out)
    display.move(500, 900, 0.5)
    image = shot("hidpi-start")
    geometry = subprocess.run(["xdotool", "getwindowgeometry", window_id()], capture_output=True, text=True).stdout
    width = int(geometry.split("Geometry: ")[1].split("x")[0])
    if image:
        check(image[0] * 2 >= width, f"2x: the view is {image[0]} of the window's {width} pixels")
        for x0, x1 in panes(image, 3):
            check(not touches_border(image, x0, x1), f"2x: the model touches pane {x0}..{x1}")
    resize(2880, 1800)
    image = shot("hidpi-2880x1800")
    if image:
        for x0, x1 in panes(image, 3):
            check(not touches_border(image, x0, x1), f"2x maximised: the model touches pane {x0}..{x1}")
    quit_viewer(proc, display)
elif scenario == "slides":
    window, fresh = os.path.join(out, "window-compare.png"), os.path.join(out, "window-fresh.png")
    proc, display = start_viewer([shadelab, "--playlist", playlist, "--screenshot", window], out)
    display.move(300, 500, 0.5)
    resize(1920, 1080)
    for _ in range(3):
        display.key("Next")
    frames = {}
    for preset in range(4, 9):  # the k_e series: one camera, one sphere; 07's caption wraps
        image = shot(f"preset{preset:02d}-1920x1080")
        if image:
            frames[preset] = (image[0], image[1], model_box(image))
        display.key("Next")
    print("k_e series (view width, height, sphere box):", frames)
    check(len(set(frames.values())) == 1, f"the k_e series is not framed alike: {frames}")
    display.key("Home")  # preset 1: compare
    compare = shot("compare-1920x1080")
    if compare:
        for x0, x1 in panes(compare, 3):
            box = model_box(compare, x0 + 2, x1 - 2)
            margin = min(box[0] - x0, x1 - 1 - box[2]) if box else 0
            print(f"compare pane {x0}..{x1}: sphere {box}, side margin {margin} px ({100 * margin / (x1 - x0):.1f}%)")
            check(margin >= 0.06 * (x1 - x0), f"compare pane {x0}..{x1}: the model is {margin} px from its side")
    display.key("Next")   # away and back: slide changes, the last two things before quitting
    display.key("Prior")
    quit_viewer(proc, display)
    proc, display = start_viewer([shadelab, "--playlist", playlist, "--screenshot", fresh], out)
    display.move(300, 500, 0.5)
    resize(1920, 1080)
    quit_viewer(proc, display)
    if compare and os.path.exists(window) and os.path.exists(fresh):
        w, h = compare[0], compare[1]
        a, b = read_png(open(window, "rb").read()), read_png(open(fresh, "rb").read())
        top = a[1] - h  # the view is the window's bottom-left w x h
        differ = sum(1 for y in range(top, a[1]) for x in range(0, w, 2) if a[2][y][x] != b[2][y][x])
        check(differ == 0, f"after a slide change {differ} pixels of the view differ from a fresh session's (a message?)")
        separator = lambda p: abs(p[0] - 150) <= 12 and abs(p[1] - 150) <= 12 and abs(p[2] - 160) <= 12
        for x0, _ in panes(compare, 3)[1:]:
            in_window = sum(1 for y in range(top, a[1]) if any(separator(a[2][y][x]) for x in range(x0 - 2, x0 + 2)))
            in_view = sum(1 for y in range(h) if any(separator(compare[2][y][x]) for x in range(x0 - 2, x0 + 2)))
            check(in_window > 0.8 * h, f"no separator at x {x0} in the window: {in_window} of {h} rows")
            check(in_view < 0.05 * h, f"a separator at x {x0} in the F12 image: {in_view} of {h} rows")
elif scenario == "labels":
    # The light labels keep off the models: where the window's view differs from F12's image (the
    # overlays) on a model's pixels, only the markers' arrows and rings may be, not a label's box.
    # And E's formula in a 1200x800 window on the k_e series' sphere, which fills the view's height: in
    # its own band above the view, it covers none of it (it covered the sphere's lower part).
    single = os.path.join(out, "ke-only")
    os.makedirs(single, exist_ok=True)
    ke = sorted(f for f in os.listdir(playlist) if f.startswith("04"))[0]
    shutil.copy(os.path.join(playlist, ke), single)
    for name, extra, size in (("scale1", [], (1920, 1080)), ("ui1.5", ["--ui-scale", "1.5"], (1920, 1080)),
                              ("formula-1200x800", ["--formula"], (1200, 800))):
        window = os.path.join(out, f"labels-{name}.png")
        source = single if name.startswith("formula") else playlist
        proc, display = start_viewer([shadelab, "--playlist", source, "--screenshot", window] + extra, out)
        display.move(300, 500, 0.5)
        resize(*size)
        display.move(5, size[1] - 5, 0.5)  # the cursor off the view
        view = shot(f"labels-{name}-view")
        quit_viewer(proc, display)
        if not view or not os.path.exists(window):
            continue
        w, h, rows = view
        win = read_png(open(window, "rb").read())
        top = win[1] - h
        for x0, x1 in panes(view, 1 if name.startswith("formula") else 3):
            background = rows[h - 1][x0]
            covered = sum(1 for y in range(h) for x in range(x0 + 3, x1 - 3)
                          if max(abs(a - b) for a, b in zip(rows[y][x], background)) > 6
                          and max(abs(a - b) for a, b in zip(rows[y][x], win[2][top + y][x])) > 40)
            model = model_pixels(view, x0 + 3, x1 - 3) * 4
            print(f"{name} pane {x0}..{x1}: {covered} of the model's ~{model} pixels covered by overlays")
            check(covered < 0.003 * model, f"{name}: overlays cover {covered} of the model's ~{model} pixels in pane {x0}..{x1}")
elif scenario == "viewtext":
    # The view's text is sized from the window's height, not the panel's scale: at 1920x1080, with the
    # panel at UI scale 0.8, the caption's text lines are at least as tall as 3% of the window's height
    # makes DejaVu Sans' ascender-to-descender (0.85 of its size; 0.78 counted with anti-aliasing); and a playing k_e ramp shows a large
    # live readout ("k_e = ...") in the specular colour at the view's top left.
    window = os.path.join(out, "viewtext.png")
    proc, display = start_viewer([shadelab, "--playlist", playlist, "--ui-scale", "0.8", "--screenshot", window], out)
    display.move(300, 500, 0.5)
    resize(1920, 1080)
    display.move(5, 1075, 0.5)
    quit_viewer(proc, display)
    width, height, rows = read_png(open(window, "rb").read())
    band = lambda p: abs(p[0] - 24) <= 2 and abs(p[1] - 24) <= 2 and abs(p[2] - 30) <= 2  # the caption band
    band_rows = [y for y in range(height) if band(rows[y][8]) and band(rows[y][400])]
    lines, run = [], 0
    for y in range(band_rows[0], band_rows[-1] + 1) if band_rows else []:
        lit = any(min(rows[y][x]) > 150 for x in range(8, 1300))
        if lit:
            run += 1
        elif run:
            lines.append(run)
            run = 0
    print(f"caption band rows {band_rows[0] if band_rows else None}..{band_rows[-1] if band_rows else None}, text lines {lines} px")
    check(len(lines) >= 2 and min(lines[1:]) >= 0.78 * 0.03 * 1080,
          f"the caption's lines are {lines[1:]} px tall, under 3% of the 1080-px window")
    animated = os.path.join(out, "readout.png")
    subprocess.run([shadelab, "--size", "960x540", "--animate", "ke=1..1000:log:4", "--frames", "40", "--screenshot", animated],
                   check=True, env=dict(os.environ, XDG_CONFIG_HOME=os.path.join(out, "config")))
    width, height, rows = read_png(open(animated, "rb").read())
    gold = sum(1 for y in range(height // 3) for x in range(0, 480)
               if rows[y][x][0] > 170 and 0.65 * rows[y][x][0] < rows[y][x][1] < 0.9 * rows[y][x][0] and rows[y][x][2] < 0.5 * rows[y][x][0])
    print(f"readout: {gold} gold pixels at the view's top left")
    check(gold > 300, f"no live k_e readout over the view while the ramp plays ({gold} gold pixels)")
elif scenario == "shaderview":
    # S puts the shader over the view for the hall: at 1920x1080 the term lines' bars (ambient blue, a
    # solid bar as high as a line) are at least 2% of the window's height tall (the view text; the
    # panel's listing is 14 px), and the wrapped code reaches across the box (past 45% of the view).
    window = os.path.join(out, "shaderview.png")
    proc, display = start_viewer([shadelab, "--playlist", playlist, "--screenshot", window], out)
    display.move(300, 500, 0.5)
    resize(1920, 1080)
    display.move(1700, 1000, 0.3)
    display.key("s")
    quit_viewer(proc, display)
    width, height, rows = read_png(open(window, "rb").read())
    view_width = 1440  # the panel is 30 font heights (480 px) at scale 1
    ambient = lambda p: abs(p[0] - 110) <= 3 and abs(p[1] - 175) <= 3 and abs(p[2] - 255) <= 3
    best = 0
    for x in range(0, 80):
        run = 0
        for y in range(height):
            run = run + 1 if ambient(rows[y][x]) else 0
            best = max(best, run)
    # Code and comment text (comments are grey, about 79 with anti-aliasing) over the darkened scene
    # (at most about 35), below the pane labels.
    text_far = sum(1 for y in range(260, height) for x in range(int(0.45 * view_width), int(0.6 * view_width))
                   if max(rows[y][x]) > 70)
    print(f"shader view: ambient bar {best} px tall, {text_far} light pixels between 45% and 60% of the view")
    check(best >= 0.02 * 1080, f"the shader view's lines are {best} px tall (under 2% of the 1080-px window)")
    check(text_far > 500, f"the shader view's code does not reach across 60% of the view ({text_far} pixels)")
elif scenario == "animcap":
    # A playing animation draws at most one frame per display refresh (Xvfb reports none or 60 Hz: 60),
    # not as fast as llvmpipe can: frames counted by -v over the session's length, plus the CPU it took.
    import re
    proc, display = start_viewer([shadelab, "--size", "320x180", "--hide-panel", "--animate", "light-orbit"], out)
    start = time.monotonic()
    fields = lambda: open(f"/proc/{proc.pid}/stat").read().rsplit(")", 1)[1].split()
    cpu = lambda: (int(fields()[11]) + int(fields()[12])) / os.sysconf("SC_CLK_TCK")
    before, t0 = cpu(), time.monotonic()
    time.sleep(4.0)
    share = (cpu() - before) / (time.monotonic() - t0)
    err = quit_viewer(proc, display)
    elapsed = time.monotonic() - start
    frames = int(re.search(r"(\d+) frames, median", err).group(1)) if re.search(r"(\d+) frames, median", err) else 0
    print(f"animation: {frames} frames in {elapsed:.1f} s ({frames / elapsed:.0f} per s), {100 * share:.0f}% of a core")
    check(0 < frames <= 61 * elapsed + 5, f"{frames} frames in {elapsed:.1f} s: more than 60 a second")
elif scenario == "lightdrag":
    # A point light on the viewing axis, between the eye (0, 1.5, 4.8) and the target: its marker is
    # at the view's centre, (400, 300) in the view, (400, 324) on the screen under the status strip.
    saved = os.path.join(out, "dragged.json")
    proc, display = start_viewer([shadelab, "--size", "800x600", "--hide-panel", "--mesh", "icosphere:4",
                                  "--light", "point:0,0.75,2.4", "--save-scene", saved], out)
    def brightest_x(image):
        width, height, rows = image
        best = max(((sum(rows[y][x]), x) for y in range(0, height, 2) for x in range(0, width, 2)))
        return best[1]
    display.move(400, 324, 0.5)
    before = shot("before")
    display.button(1, True)
    time.sleep(1.0)  # ImGui reads the press where the cursor is at the next frame: let it come first
    for i in range(1, 16):
        display.move(400 + 10 * i, 324)
    display.button(1, False)
    display.move(700, 100, 0.3)  # away from the marker, so the screenshot shows the surface
    after = shot("after")
    quit_viewer(proc, display)
    import json
    light = json.load(open(saved))["lights"][0]["position"]
    check(0.3 < light[0] < 0.8, f"dragged 150 px right: light x {light[0]:.3f} (about 0.53 expected)")
    # In the plane through the light that faces the camera: its depth along the view axis is kept.
    eye, forward = (0.0, 1.5, 4.8), (0.0, -1.5 / 5.029, -4.8 / 5.029)
    depth = sum((light[k] - eye[k]) * forward[k] for k in range(3))
    check(abs(depth - 2.5145) < 0.05, f"dragged light left its plane: depth {depth:.3f}")
    check(abs(json.load(open(saved))["camera"]["eye"][0]) < 1e-6, "the drag orbited the camera")
    if before and after:
        check(brightest_x(after) > brightest_x(before) + 20,
              f"the highlight did not follow the light: x {brightest_x(before)} -> {brightest_x(after)}")
elif scenario == "remember":
    import json
    config = os.path.join(out, "config")
    prefs = os.path.join(config, "shadelab", "viewer.json")
    def geometry():
        text = subprocess.run(["xdotool", "getwindowgeometry", window_id()], capture_output=True, text=True).stdout
        return tuple(int(v) for v in text.split("Geometry: ")[1].split()[0].split("x"))
    proc, display = start_viewer([shadelab, "--size", "640x360"], out, config)
    first = geometry()
    resize(1000, 700)
    display.move(300, 300, 0.3)
    display.key("equal", ctrl=True)  # UI scale 1.25
    quit_viewer(proc, display)
    saved = json.load(open(prefs)) if os.path.exists(prefs) else {}
    check(saved.get("window", {}).get("width") == 1000 and saved.get("window", {}).get("height") == 700,
          f"the window's size was not remembered: {saved}")
    check(abs(saved.get("ui_scale", 0) - 1.25) < 1e-3, f"Ctrl+= did not give UI scale 1.25: {saved}")
    proc, display = start_viewer([shadelab, "--size", "640x360"], out, config)
    check(geometry() == (1000, 700), f"reopened at {geometry()}, not where it was left (1000x700)")
    quit_viewer(proc, display)
    proc, display = start_viewer([shadelab, "--size", "640x360", "--reset-layout"], out, config)
    check(geometry() == first, f"--reset-layout opened at {geometry()}, not the default {first}")
    quit_viewer(proc, display)
    check(abs(json.load(open(prefs)).get("ui_scale", 0) - 1.0) < 1e-3, "--reset-layout kept the UI scale")
elif scenario == "textfield":
    import json
    # Where the File section's path field is: a scripted run with the same layout, and the widest row
    # of the field's colour (ImGui's frame background over the panel) in the panel.
    args = [shadelab, "--size", "640x360", "--panel-sections", "file"]
    first = os.path.join(out, "layout.png")
    subprocess.run(args + ["--frames", "3", "--screenshot", first], check=True,
                   env=dict(os.environ, XDG_CONFIG_HOME=os.path.join(out, "config")))
    width, height, rows = read_png(open(first, "rb").read())
    field = lambda p: abs(p[0] - 29) <= 4 and abs(p[1] - 47) <= 4 and abs(p[2] - 74) <= 4
    best = max(range(height), key=lambda y: sum(1 for x in range(640, width) if field(rows[y][x])))
    xs = [x for x in range(640, width) if field(rows[best][x])]
    check(len(xs) > (width - 640) // 2, f"no path field found in the panel (row {best}: {len(xs)} pixels)")
    fx, fy = (xs[0] + xs[-1]) // 2 if xs else 0, best
    for leave, mode in (("click", "gouraud"), ("Escape", "phong")):
        saved = os.path.join(out, f"after-{leave}.json")
        proc, display = start_viewer(args + ["--save-scene", saved], out)
        display.move(fx, fy, 0.3)
        display.button(1, True)
        display.button(1, False)
        display.key("x")       # typed into the field
        if leave == "click":
            display.move(320, 200, 0.3)  # a click on the view elsewhere takes the keyboard back
            display.button(1, True)
            display.button(1, False)
        else:
            display.key("Escape")
        display.key("2" if mode == "gouraud" else "3")  # a shortcut again, not a character in the field
        display.key("q")
        try:
            proc.communicate(timeout=30)
        except subprocess.TimeoutExpired:
            proc.kill()
            check(False, f"after {leave}: q did not quit (the field kept the keyboard)")
            continue
        shading = json.load(open(saved))["shading"] if os.path.exists(saved) else None
        check(shading == mode, f"after {leave}: the key went to the field, shading is {shading}")
else:
    sys.exit(f"unknown scenario {scenario}")

if failures:
    sys.exit("; ".join(failures))
print(f"{scenario}: ok")
