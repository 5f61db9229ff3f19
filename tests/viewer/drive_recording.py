#!/usr/bin/env python3
"""Records the playing --animate view with Ctrl+R (X input events, see xinput.py), pauses and quits, and
checks the red REC marker over the view while it records, not before or after (grabbed from the X
screen), and the file: one timestamped MP4 in the working folder, no temporary left, the index ("moov")
before the media data, and about as many frames' worth of time as the recording ran (the sample table's count
is read from the file's boxes; the frames themselves are decoded in tests/video).

usage: drive_recording.py SHADELAB OUTDIR     (run inside an X server: see xvfb_run.sh)
Exits 77 (skipped) when libX11/libXtst cannot be loaded; where the build has no video encoding the
viewer says so in its message and no file is written, which this test reports as a failure.
"""
import glob, os, struct, sys, time

from xinput import quit_viewer, start_viewer

shadelab, out = sys.argv[1], sys.argv[2]
os.makedirs(out, exist_ok=True)
for f in glob.glob(os.path.join(out, "*")) + glob.glob(os.path.join(out, ".shadelab*")):
    os.remove(f)
proc, display = start_viewer([shadelab, "--size", "320x240", "--animate", "light-orbit:2"], out)


def red_pixels():
    """The REC marker's red dot: pixels of (230, 30, 30) at the view's top right (the view is 400 wide, the
    panel's least width taking the rest of the window), as the screen shows it (the window sits at the
    origin, the status strip's 24 rows above the view). The sphere's orange has green at 0.38 of red."""
    _, _, rows = display.grab(200, 24, 200, 120)
    return sum(1 for row in rows for p in row if abs(p[0] - 230) <= 25 and p[1] < 50 and p[2] < 50)


before = red_pixels()
display.key("r", ctrl=True)   # start recording the playing view
time.sleep(1.0)
during = red_pixels()         # a red REC marker at the view's top right while recording (issue 31)
time.sleep(1.0)
display.key("space")          # pause: a recording keeps drawing (and recording) a still view
time.sleep(0.5)
display.key("r", ctrl=True)   # stop: the file is finished and renamed
time.sleep(0.3)
after = red_pixels()
quit_viewer(proc, display)


def boxes(data, start, end):
    """The MP4 boxes between start and end: (type, payload start, payload end)."""
    at = start
    while at + 8 <= end:
        size, kind = struct.unpack(">I4s", data[at:at + 8])
        if size < 8:
            break
        yield kind.decode("latin-1"), at + 8, at + size
        at += size


def sample_count(data):
    """The video track's number of samples (frames), from moov/trak/mdia/minf/stbl/stsz."""
    def find(path, start, end):
        for kind, s, e in boxes(data, start, end):
            if kind == path[0]:
                return (s, e) if len(path) == 1 else find(path[1:], s, e)
        return None
    stsz = find(["moov", "trak", "mdia", "minf", "stbl", "stsz"], 0, len(data))
    return struct.unpack(">I", data[stsz[0] + 8:stsz[0] + 12])[0] if stsz else -1


failures = []
print(f"REC marker: {before} red pixels before recording, {during} while, {after} after")
if not (before == 0 and during > 20 and after == 0):
    failures.append(f"REC marker: {before} red pixels before recording, {during} while, {after} after (0, >20, 0)")
videos = glob.glob(os.path.join(out, "shadelab-*.mp4"))
if proc.returncode != 0:
    failures.append(f"exit status {proc.returncode}")
if len(videos) != 1:
    failures.append(f"{len(videos)} recordings in the working folder, expected 1")
if glob.glob(os.path.join(out, ".shadelab*")):
    failures.append("a temporary file was left: " + ", ".join(glob.glob(os.path.join(out, ".shadelab*"))))
if len(videos) == 1:
    data = open(videos[0], "rb").read()
    order = [kind for kind, _, _ in boxes(data, 0, len(data))]
    if "moov" not in order or "mdat" not in order or order.index("moov") > order.index("mdat"):
        failures.append(f"top-level boxes {order}: the index (moov) must come before the media (mdat)")
    frames = sample_count(data)
    # About 3.9 s between the two presses (2.5 s of sleeps, 1.4 s of key pauses) at 30 fps: ~117 frames
    # of real time (measured 110), whatever the frame rate the viewer reached.
    if not 80 <= frames <= 150:
        failures.append(f"{frames} frames for about 3 s of recording at 30 fps")
if failures:
    sys.exit("; ".join(failures))
print(f"recorded {videos[0]}: {frames} frames")
