#!/usr/bin/env python3
"""Records the playing --animate view with Ctrl+R (X input events, see xinput.py), pauses and quits, and
checks the file: one timestamped MP4 in the working folder, no temporary left, the index ("moov") before
the media data, and about as many frames' worth of time as the recording ran (the sample table's count
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
display.key("r", ctrl=True)   # start recording the playing view
time.sleep(2.0)
display.key("space")          # pause: a recording keeps drawing (and recording) a still view
time.sleep(0.5)
display.key("r", ctrl=True)   # stop: the file is finished and renamed
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
