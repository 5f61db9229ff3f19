#!/usr/bin/python3
"""The web page (build-web/, issue 29) in headless chromium, driven through chromedriver.

    /usr/bin/python3 tests/web/test_web.py --site build-web [--shadelab build/shadelab]
                     [-k PATTERN]... [--keep DIR] [-v]

(./dev test-web builds the page first and runs this.) Debian's python3-selenium, chromium and
chromium-driver (third_party/packages-web.txt); nothing else: unittest, a PNG reader and writer and a
.glb packer of its own. One chromium session serves every test (the 2x device-scale screenshot opens
a second one); the page is loaded from file:// except in HttpServer, which serves the folder with
`python3 -m http.server` on a free port of 127.0.0.1.

Two kinds of tests:

- Api*: the program's exported functions (shadelab.module.ccall: sl_apply, sl_read_pixels, ...; the
  program is a factory, -sMODULARIZE, so there is no global Module: the page hands its instance out
  as window.shadelab.module).
- HttpServer: one parity check over http://127.0.0.1; Screenshots: the page at 1920x1080 and at a 2x
  device scale, opened with ?preset=6&layout=compare (so they need the panel's preset= too).
- Panel*: the panel's contract (window.shadelab, the named form elements, #next, #message, the keys,
  the URL). Until the page (app/web/src/) offers it they FAIL, each with a line saying what is
  missing; they are never skipped.
- SourceSize: the page's JavaScript in small parts (tests/web/js_size.py: functions of at most 40
  lines, files of at most 400).

Parity tolerance. The page draws with WebGL2 on SwiftShader (through ANGLE), `shadelab --output`
with Mesa's llvmpipe. Both rasterise by the same rules, so the pictures agree except where the two
differ in the last bits: float precision of the shading (a few 1/255 in steep highlights), which
pixel centre falls inside an edge that runs exactly through it (silhouettes and pane borders), and
shadow-map depth comparisons right at a shadow's edge. Measured over all 23 lecture presets at
320x240, --msaa 1 (test ApiParity.test_every_preset; -v prints the table, docs/web.md has it):
see the figures beside PIXEL_THRESHOLD below. A frame matches its reference when

    at most BUDGET_FRACTION of its pixels differ by more than PIXEL_THRESHOLD/255 in any channel
    (in a diff layout's |A - B| pane: 2 x --diff-factor, since a last bit in A and in B shows there
    multiplied), and the mean channel difference of the other pixels is at most MEAN_LIMIT/255.

A pixel budget plus a mean rather than a bare maximum: a silhouette pixel, or a row of pixels on an
edge that runs exactly through their centres (the two rasterisers break that tie on opposite sides:
the material_panels model's bottom edges), legitimately differs by up to 235/255, while a wrong
exponent, light, term or mode moves hundreds of pixels past the threshold or all of them by a
little, which the budget or the mean catches (ApiParity.test_tolerance_catches_changes checks that
k_e 32 -> 40, the light moved by 0.3 and Gouraud for Phong each fail).
"""
import argparse
import base64
import json
import math
import os
import shutil
import socket
import struct
import subprocess
import sys
import tempfile
import time
import unittest
import urllib.parse
import zlib

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
PRESET_DIR = os.path.join(ROOT, "assets", "scenes", "lecture")
MODEL_DIR = os.path.join(ROOT, "assets", "models")
PAGE_PRESET_DIR = "/share/shadelab/scenes/lecture"
PAGE_MODEL_DIR = "/share/shadelab/models"
SIZE = "320x240"

# The tolerance (see the docstring). Measured 2026-12-03 over all 23 presets at 320x240 (76,800
# pixels), SwiftShader (Chromium 156) against llvmpipe (Mesa 22.3.6): the worst preset by pixels
# over 4/255, 16-occlusion (shadow-map edges), had 194 (0.25%); single-object presets 5-26, on
# silhouettes (max up to 176/255 there); the .glb models up to 197 (material_panels, an edge row).
# The mean of the other pixels was at most 0.009/255 over the presets and 0.032/255 (checker_globe,
# texture filtering) over the models. The budget is about twice the worst count, the mean limit three
# times the worst mean; k_e 32 against 40 has 1420 pixels over and fails.
PIXEL_THRESHOLD = 4      # /255, per channel
BUDGET_FRACTION = 0.005  # of the frame's pixels
MEAN_LIMIT = 0.1         # /255, over every channel of the pixels within the threshold

ARGS = None          # the parsed command line
DRIVER = None        # the shared chromium session
CONSOLE = []         # every browser console entry seen, in order
WORK = None          # a temporary folder for this run


# --- PNG and GLB --------------------------------------------------------------------------------

def read_png(path):
    """(width, height, RGBA bytes top-down) of an 8-bit RGB or RGBA, non-interlaced PNG."""
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError(path + ": not a PNG")
    pos, idat, header = 8, [], None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat.append(body)
        pos += 12 + length
    width, height, depth, colour, _, _, interlace = header
    if depth != 8 or colour not in (2, 6) or interlace:
        raise ValueError(path + ": only 8-bit RGB/RGBA non-interlaced PNGs are read here")
    channels = 4 if colour == 6 else 3
    raw = zlib.decompress(b"".join(idat))
    stride = width * channels
    out = bytearray(height * stride)
    previous = bytearray(stride)
    for y in range(height):
        kind = raw[y * (stride + 1)]
        line = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        if kind == 1:
            for i in range(channels, stride):
                line[i] = (line[i] + line[i - channels]) & 255
        elif kind == 2:
            line = bytearray((a + b) & 255 for a, b in zip(line, previous))
        elif kind == 3:
            for i in range(stride):
                left = line[i - channels] if i >= channels else 0
                line[i] = (line[i] + ((left + previous[i]) >> 1)) & 255
        elif kind == 4:
            for i in range(stride):
                a = line[i - channels] if i >= channels else 0
                b = previous[i]
                c = previous[i - channels] if i >= channels else 0
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        out[y * stride:(y + 1) * stride] = line
        previous = line
    if channels == 3:
        rgba = bytearray(width * height * 4)
        rgba[0::4], rgba[1::4], rgba[2::4] = out[0::3], out[1::3], out[2::3]
        rgba[3::4] = b"\xff" * (width * height)
        out = rgba
    return width, height, bytes(out)


def write_png(path, width, height, rgba):
    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))
    stride = width * 4
    raw = b"".join(b"\x00" + rgba[y * stride:(y + 1) * stride] for y in range(height))
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0))
                + chunk(b"IDAT", zlib.compress(raw, 6)) + chunk(b"IEND", b""))


def pack_glb(gltf_path):
    """The .gltf at gltf_path as one .glb: header, JSON chunk, BIN chunk holding every buffer and
    every image (data: URIs and files beside it), 4-byte aligned."""
    doc = json.load(open(gltf_path))
    folder = os.path.dirname(gltf_path)

    def load(uri):
        if uri.startswith("data:"):
            return base64.b64decode(uri.split(",", 1)[1])
        return open(os.path.join(folder, urllib.parse.unquote(uri)), "rb").read()

    blob = bytearray()

    def append(data):
        offset = len(blob)
        blob.extend(data)
        blob.extend(b"\x00" * (-len(blob) % 4))
        return offset

    starts = [append(load(b["uri"])) for b in doc.get("buffers", [])]
    for view in doc.get("bufferViews", []):
        view["byteOffset"] = view.get("byteOffset", 0) + starts[view["buffer"]]
        view["buffer"] = 0
    views = doc.setdefault("bufferViews", [])
    for image in doc.get("images", []):
        if "uri" not in image:
            continue
        uri = image.pop("uri")
        data = load(uri)
        if "mimeType" not in image:
            image["mimeType"] = "image/png" if data[:4] == b"\x89PNG" else "image/jpeg"
        views.append({"buffer": 0, "byteOffset": append(data), "byteLength": len(data)})
        image["bufferView"] = len(views) - 1
    doc["buffers"] = [{"byteLength": len(blob)}]
    text = json.dumps(doc, separators=(",", ":")).encode()
    text += b" " * (-len(text) % 4)
    total = 12 + 8 + len(text) + 8 + len(blob)
    return (struct.pack("<4sII", b"glTF", 2, total) + struct.pack("<I4s", len(text), b"JSON") + text
            + struct.pack("<I4s", len(blob), b"BIN\x00") + bytes(blob))


def compressed_gltf(extension):
    """A minimal glTF (one triangle) whose extensionsRequired names `extension`."""
    positions = struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0)
    return json.dumps({
        "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
        "extensionsUsed": [extension], "extensionsRequired": [extension],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                       "min": [0, 0, 0], "max": [1, 1, 0]}],
        "bufferViews": [{"buffer": 0, "byteLength": 36}],
        "buffers": [{"byteLength": 36, "uri": "data:application/octet-stream;base64,"
                     + base64.b64encode(positions).decode()}],
    })


# --- comparing frames ---------------------------------------------------------------------------

def difference(a, b, thresholds=None):
    """Per-pixel largest channel difference between two RGBA byte strings of the same size:
    (max, mean of the pixels within their threshold, pixels over their threshold, per-pixel list).
    thresholds: per pixel, else PIXEL_THRESHOLD everywhere."""
    assert len(a) == len(b), "sizes differ: %d vs %d bytes" % (len(a), len(b))
    per_pixel = []
    within_total = within = over = 0
    for i in range(0, len(a), 4):
        d0, d1, d2, d3 = abs(a[i] - b[i]), abs(a[i + 1] - b[i + 1]), abs(a[i + 2] - b[i + 2]), abs(a[i + 3] - b[i + 3])
        d = max(d0, d1, d2, d3)
        per_pixel.append(d)
        if d > (thresholds[i >> 2] if thresholds else PIXEL_THRESHOLD):
            over += 1
        else:
            within += 1
            within_total += d0 + d1 + d2 + d3
    return max(per_pixel), within_total / max(1, 4 * within), over, per_pixel


def pane_thresholds(result, args):
    """PIXEL_THRESHOLD, and in a diff layout's |A - B| pane twice the factor: a last-bit difference in
    A and in B shows there multiplied by --diff-factor."""
    width, height = result["width"], result["height"]
    factor = float(args[args.index("--diff-factor") + 1]) if "--diff-factor" in args else 4.0
    out = [PIXEL_THRESHOLD] * (width * height)
    for p in result.get("panes", []):
        if p.get("difference"):
            t = max(PIXEL_THRESHOLD, int(2 * factor))
            for y in range(p["y"], min(height, p["y"] + p["height"])):
                out[y * width + p["x"]:y * width + min(width, p["x"] + p["width"])] = [t] * min(p["width"], width - p["x"])
    return out


def diff_image(per_pixel, width, height):
    out = bytearray()
    for d in per_pixel:
        v = min(255, d * 16)
        out += bytes((v, v if d <= PIXEL_THRESHOLD else 0, v if d <= PIXEL_THRESHOLD else 0, 255))
    return bytes(out)


def verdict(stats, pixels):
    worst, mean, over, per_pixel = stats
    budget = int(BUDGET_FRACTION * pixels)
    ok = over <= budget and mean <= MEAN_LIMIT
    line = "max %d/255, %d px over the threshold (budget %d), the others' mean %.3f/255 (limit %g), %d px > 16" % (
        worst, over, budget, mean, MEAN_LIMIT, sum(1 for d in per_pixel if d > 16))
    return ok, line


# --- the browser --------------------------------------------------------------------------------

def chromium(width=1280, height=900, scale=None):
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service
    options = webdriver.ChromeOptions()
    for a in ("--headless=new", "--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
              "--window-size=%d,%d" % (width, height), "--allow-file-access-from-files"):
        options.add_argument(a)
    if scale:
        options.add_argument("--force-device-scale-factor=%g" % scale)
    options.binary_location = "/usr/bin/chromium"
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    driver = webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=options)
    driver.set_script_timeout(120)
    return driver


def drain_console(driver=None):
    entries = (driver or DRIVER).get_log("browser")
    CONSOLE.extend(entries)
    return entries


def site_url(query=""):
    url = "file://" + urllib.parse.quote(os.path.join(os.path.abspath(ARGS.site), "index.html"))
    return url + ("?" + query if query else "")


def wait_for(driver, script, what, timeout=30):
    end = time.time() + timeout
    while True:
        value = driver.execute_script(script)
        if value:
            return value
        if time.time() > end:
            raise AssertionError("timed out after %ds waiting for %s" % (timeout, what))
        time.sleep(0.05)


# The program (the page's emscripten module instance, window.shadelab.module) has run main() once its
# ccall exists.
PROGRAM_READY = ("const m = window.shadelab && window.shadelab.module; "
                 "return !!m && m.calledRun === true && typeof m.ccall === 'function'")


def load_page(driver, query="", url=None):
    driver.get(url or site_url(query))
    wait_for(driver, PROGRAM_READY, "the program (index.js) to run")
    # The placeholder sets the title, the panel sets shadelab.ready, after their first frame.
    wait_for(driver, "return document.title === 'shadelab ready' || "
             "(window.shadelab !== undefined && window.shadelab.ready === true)", "the first frame")


def ccall(name, types=(), args=(), driver=None):
    text = (driver or DRIVER).execute_script(
        "return window.shadelab.module.ccall(arguments[0], 'string', arguments[1], arguments[2]);", name, list(types), list(args))
    return json.loads(text)


def apply(args, driver=None):
    return ccall("sl_apply", ["string"], [json.dumps(args)], driver)


READ_PIXELS = """
const Module = window.shadelab.module;
const r = JSON.parse(Module.ccall('sl_read_pixels', 'string', [], []));
if (r.error) return r;
const p = Module.ccall('sl_frame_data', 'number', [], []);
const bytes = Module.HEAPU8.subarray(p, p + r.width * r.height * 4);
let s = '';
for (let i = 0; i < bytes.length; i += 0x8000) s += String.fromCharCode.apply(null, bytes.subarray(i, i + 0x8000));
return {width: r.width, height: r.height, base64: btoa(s)};
"""


def page_pixels(driver=None):
    r = (driver or DRIVER).execute_script(READ_PIXELS)
    if "error" in r:
        raise AssertionError("sl_read_pixels: " + r["error"])
    return r["width"], r["height"], base64.b64decode(r["base64"])


def write_to_page(path, data, driver=None):
    """A file into the program's memory file system (the page's own files are under /share)."""
    (driver or DRIVER).execute_script(
        "const b = atob(arguments[1]); const a = new Uint8Array(b.length);"
        "for (let i = 0; i < b.length; ++i) a[i] = b.charCodeAt(i);"
        "window.shadelab.module.FS.writeFile(arguments[0], a);", path, base64.b64encode(data).decode())


def native(args, output):
    cmd = [ARGS.shadelab] + args + ["--output", output]
    r = subprocess.run(cmd, capture_output=True, text=True, timeout=300)
    if r.returncode != 0:
        raise AssertionError("%s: exit %d: %s" % (" ".join(cmd), r.returncode, r.stderr.strip()))
    return read_png(output)


def keep(name, width, height, rgba):
    if ARGS.keep:
        os.makedirs(ARGS.keep, exist_ok=True)
        write_png(os.path.join(ARGS.keep, name), width, height, rgba)


def presets():
    return sorted(f for f in os.listdir(PRESET_DIR) if f.endswith(".json"))


class PageTest(unittest.TestCase):
    """Every test ends with the console checked: no SEVERE entry (console.error, an uncaught
    exception, a failed load) unless the test expects one."""
    console_errors_expected = False

    def setUp(self):
        drain_console()

    def tearDown(self):
        entries = drain_console()
        if not self.console_errors_expected:
            severe = [e["message"] for e in entries if e.get("level") == "SEVERE"]
            hint = " (index.html should name an icon, e.g. <link rel=\"icon\" href=\"data:,\">, or a server " \
                "asks for /favicon.ico)" if any("favicon.ico" in m for m in severe) else ""
            self.assertEqual(severe, [], "errors in the browser console" + hint)

    def assertParity(self, page_args, native_args, name):
        """The page given page_args against shadelab native_args --output, within the tolerance."""
        r = apply(page_args)
        self.assertNotIn("error", r, "sl_apply(%s)" % page_args)
        width, height, rgba = page_pixels()
        rw, rh, ref = native(native_args, os.path.join(WORK, name + ".ref.png"))
        self.assertEqual((width, height), (rw, rh), name + ": page and reference sizes")
        stats = difference(rgba, ref, pane_thresholds(r, page_args))
        ok, line = verdict(stats, width * height)
        keep(name + ".page.png", width, height, rgba)
        keep(name + ".ref.png", width, height, ref)
        if not ok:
            keep(name + ".diff.png", width, height, diff_image(stats[3], width, height))
        if ARGS.verbose:
            print("  %-34s %s" % (name, line), file=sys.stderr)
        self.assertTrue(ok, "%s: page vs shadelab --output: %s" % (name, line))
        return stats


def preset_args(preset, *more, page=True):
    folder = PAGE_PRESET_DIR if page else PRESET_DIR
    return [folder + "/" + preset] + ["--size", SIZE, "--msaa", "1"] + list(more)


# --- Api: the program's functions, on any page ---------------------------------------------------

class ApiParity(PageTest):
    @classmethod
    def setUpClass(cls):
        load_page(DRIVER, "size=" + SIZE)

    def test_every_preset(self):
        """Each lecture preset as its file says (its own layout and shading)."""
        failures, rows = [], []
        for preset in presets():
            name = preset[:-5]
            try:
                stats = self.assertParity(preset_args(preset), preset_args(preset, page=False), name)
                rows.append((name, stats))
            except AssertionError as e:
                failures.append(str(e))
        if ARGS.verbose and rows:
            for label, key in (("pixels over", lambda r: r[1][2]), ("mean", lambda r: r[1][1]),
                               ("max", lambda r: r[1][0])):
                worst = max(rows, key=key)
                print("  worst by %s: %s %s" % (label, worst[0], verdict(worst[1], 320 * 240)[1]), file=sys.stderr)
        self.assertEqual(failures, [])

    def test_layouts(self):
        """Single, compare and diff layouts (and another diff pair) of a few presets."""
        for preset in ("01-flat-gouraud-phong.json", "06-exponent-32.json", "15-coloured-lights.json"):
            for layout in (["--layout", "single", "--shading", "gouraud"], ["--layout", "compare"],
                           ["--layout", "diff"], ["--layout", "diff", "--diff", "flat,phong", "--diff-factor", "8"]):
                name = "%s-%s" % (preset[:2], "-".join(a.strip("-").replace(",", "") for a in layout))
                self.assertParity(preset_args(preset, *layout), preset_args(preset, *layout, page=False), name)

    def test_changed_values(self):
        """Values changed one after another on the scene shown (the page keeps the document and
        changes its values, as the panel does), each against a fresh --output."""
        preset = "06-exponent-32.json"
        self.assertParity(preset_args(preset), preset_args(preset, page=False), "values-start")
        steps = [["--ke", "128"], ["--ke", "128", "--shading", "gouraud"],
                 ["--ke", "8", "--layout", "compare"], ["--show", "specular", "--layout", "compare"],
                 ["--show", "diffuse"], ["--reflection", "blinn-phong", "--ke", "200"],
                 ["--fresnel", "schlick", "--ior", "1.8"], ["--specular-normalization", "energy"],
                 ["--ka", "0.4", "--kd", "0.3", "--ks", "1.2"], ["--formula"], ["--formula", "--layout", "compare"],
                 ["--light", "point:-3,4,5:color=1,0.6,0.3", "--light", "directional:1,-1,-1:intensity=0.5"],
                 ["--mesh", "icosphere:2", "--layout", "compare"],
                 ["--color", "0.2,0.4,0.9", "--specular-color", "1,0.8,0.3", "--ambient", "0.3,0.3,0.4",
                  "--background", "0.9,0.9,0.85"],
                 ["--reflection", "blinn-phong", "--anisotropy", "8,256", "--layout", "compare"]]
        for i, more in enumerate(steps):
            name = "values-%02d-%s" % (i, "".join(a.strip("-")[:6] for a in more[:3]).replace(":", ""))
            self.assertParity(preset_args(preset, *more), preset_args(preset, *more, page=False), name)

    def test_tolerance_catches_changes(self):
        """The tolerance is not so wide that a small real change passes: k_e 32 against 40, the light
        moved by 0.3, and Gouraud against Phong each fail it."""
        preset = "06-exponent-32.json"
        apply(preset_args(preset))
        width, height, page = page_pixels()
        for name, args in (("ke40", ["--ke", "40"]), ("light", ["--light", "point:3.3,4,5"]),
                           ("gouraud", ["--shading", "gouraud"])):
            _, _, ref = native(preset_args(preset, *args, page=False), os.path.join(WORK, "catch-%s.png" % name))
            ok, line = verdict(difference(page, ref), width * height)
            if ARGS.verbose:
                print("  k_e 32 against %-18s %s" % (name, line), file=sys.stderr)
            self.assertFalse(ok, "k_e 32 passed as %s: %s" % (name, line))

    def test_glb(self):
        """A .glb packed here from each small model (buffers and images in its BIN chunk), in the
        page's file system, against shadelab reading the same .glb."""
        for model in ("checker_globe", "material_panels", "lowpoly_gem"):
            glb = pack_glb(os.path.join(MODEL_DIR, model + ".gltf"))
            local = os.path.join(WORK, model + ".glb")
            open(local, "wb").write(glb)
            write_to_page("/tmp/%s.glb" % model, glb)
            more = ["--size", SIZE, "--msaa", "1", "--layout", "compare"]
            self.assertParity(["/tmp/%s.glb" % model] + more, [local] + more, "glb-" + model)

    def test_overlays(self):
        """--overlays (viewer-only in the CLI, no --output reference): the wireframe and normals add
        lines (1 px here, no geometry shader) over an unchanged picture: the pixels they leave alone
        match the plain render, and they cover a plausible share of the frame."""
        preset = "06-exponent-32.json"
        _, _, ref = native(preset_args(preset, "--layout", "compare", page=False), os.path.join(WORK, "overlays.ref.png"))
        for overlays, lo, hi in (("wireframe", 0.03, 0.5), ("vertex-normals", 0.005, 0.5), ("lights", 0.00001, 0.05)):
            r = apply(preset_args(preset, "--layout", "compare", "--overlays", overlays))
            self.assertNotIn("error", r)
            width, height, page = page_pixels()
            keep("overlays-%s.page.png" % overlays, width, height, page)
            _, _, _, per_pixel = difference(page, ref)
            changed = sum(1 for d in per_pixel if d > 24) / len(per_pixel)
            self.assertTrue(lo <= changed <= hi, "%s: %.4f of the pixels changed, expected %g..%g" % (overlays, changed, lo, hi))

    def test_refusals(self):
        """What the page cannot do is one line, and the picture stays."""
        apply(preset_args("06-exponent-32.json"))
        _, _, before = page_pixels()
        write_to_page("/tmp/broken.gltf", b'{"asset": {"version": "2.0"}, "meshes": [')
        write_to_page("/tmp/broken.json", b'{"mesh": ')
        for args, words in ((["--output", "x.png"], "--output"), (["--benchmark", "5"], "--benchmark"),
                            (["--ke", "0"], "--ke"), (["/nowhere.json"], "nowhere.json"), (["--bogus"], "bogus"),
                            (["/tmp/broken.gltf"], "broken.gltf"), (["/tmp/broken.json"], "broken.json")):
            r = apply(args)
            self.assertIn("error", r, args)
            self.assertIn(words, r["error"])
            self.assertNotIn("\n", r["error"])
        _, _, after = page_pixels()
        self.assertEqual(before, after, "a refused command line changed the picture")

    def test_compressed_gltf_refused(self):
        for extension in ("KHR_draco_mesh_compression", "EXT_meshopt_compression"):
            write_to_page("/tmp/compressed.gltf", compressed_gltf(extension).encode())
            r = apply(["/tmp/compressed.gltf"])
            self.assertIn("error", r, extension)
            self.assertIn(extension, r["error"])

    def test_size_pins_canvas(self):
        r = apply(preset_args("06-exponent-32.json", "--size", "300x200"))
        self.assertEqual((r["width"], r["height"]), (300, 200))
        page_pixels()
        self.assertEqual(DRIVER.execute_script("const c = document.getElementById('canvas'); return [c.width, c.height];"),
                         [300, 200])

    def test_describe(self):
        d = ccall("sl_describe")
        self.assertEqual([os.path.basename(p["path"]) for p in d["presets"]], presets())
        self.assertTrue(all(p["title"] and p["caption"] for p in d["presets"]))
        names = {o["name"] for o in d["options"]}
        for option in ("--ke", "--layout", "--shading", "--show", "--overlays", "--formula", "--light"):
            self.assertIn(option, names)


class ApiUrlSize(PageTest):
    def test_size_param_pins_canvas(self):
        """?size=WxH pins the canvas's pixel size (placeholder and panel alike)."""
        load_page(DRIVER, "size=400x300")
        size = DRIVER.execute_script("const c = document.getElementById('canvas'); return [c.width, c.height];")
        self.assertEqual(size, [400, 300])


class HttpServer(PageTest):
    """The folder served by a static server (python3 -m http.server), as GitHub Pages would."""

    def test_served_page_matches(self):
        with socket.socket() as s:
            s.bind(("127.0.0.1", 0))
            port = s.getsockname()[1]
        server = subprocess.Popen([sys.executable, "-m", "http.server", str(port), "--bind", "127.0.0.1",
                                   "--directory", os.path.abspath(ARGS.site)],
                                  stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        try:
            end = time.time() + 20
            while True:
                try:
                    socket.create_connection(("127.0.0.1", port), timeout=1).close()
                    break
                except OSError:
                    if time.time() > end:
                        raise
                    time.sleep(0.1)
            load_page(DRIVER, url="http://127.0.0.1:%d/?size=%s" % (port, SIZE))
            preset = "07-exponent-128.json"
            self.assertParity(preset_args(preset, "--layout", "compare"),
                              preset_args(preset, "--layout", "compare", page=False), "http-07-compare")
        finally:
            server.terminate()
            server.wait(10)


class Screenshots(PageTest):
    """The page as a person sees it, saved under --keep (else into the run's temporary folder):
    1920x1080 and a 2x device scale (960x540 CSS pixels, 1920x1080 device pixels). Look at them."""

    def shoot(self, driver, name, css_width, css_height, scale):
        # The viewport (not the window, which counts the browser's frame) is css_width x css_height.
        outer = driver.execute_script("return [outerWidth - innerWidth, outerHeight - innerHeight];")
        driver.set_window_size(css_width + outer[0], css_height + outer[1])
        load_page(driver, "preset=6&layout=compare")
        time.sleep(0.5)
        path = os.path.join(ARGS.keep or WORK, name)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        driver.save_screenshot(path)
        print("  screenshot: %s" % path, file=sys.stderr)
        width, height, rgba = read_png(path)
        self.assertEqual((width, height), (css_width * scale, css_height * scale), path)
        message = driver.execute_script("const m = document.getElementById('message');"
                                        "return m && !m.hidden ? m.textContent : null;")
        self.assertIsNone(message, "the page shows a message for ?preset=6&layout=compare (%s)" % path)
        colours = {rgba[i:i + 3] for i in range(0, len(rgba), 4 * 97)}
        self.assertGreater(len(colours), 20, path + " looks blank")

    def test_1920x1080(self):
        try:
            self.shoot(DRIVER, "page-1920x1080.png", 1920, 1080, 1)
        finally:
            DRIVER.set_window_size(1280, 900)

    def test_device_scale_2(self):
        driver = chromium(960, 540, scale=2)
        try:
            self.assertEqual(driver.execute_script("return devicePixelRatio;"), 2)
            self.shoot(driver, "page-960x540@2x.png", 960, 540, 2)
            severe = [e["message"] for e in driver.get_log("browser") if e.get("level") == "SEVERE"]
            self.assertEqual(severe, [])
            # The panel's contract: an unpinned canvas has CSS size x devicePixelRatio pixels.
            self.assertTrue(driver.execute_script("return window.shadelab !== undefined"),
                            "the panel (window.shadelab) is not there yet: the canvas's device pixels are not checked")
            size = driver.execute_script("const c = document.getElementById('canvas'); const r = c.getBoundingClientRect();"
                                         "return [c.width, c.height, r.width, r.height];")
            self.assertAlmostEqual(size[0], size[2] * 2, delta=2, msg="canvas width vs its CSS width x 2: %s" % size)
            self.assertAlmostEqual(size[1], size[3] * 2, delta=2, msg="canvas height vs its CSS height x 2: %s" % size)
        finally:
            driver.quit()


# --- Panel: the HTML panel's contract (app/web/src/) -----------------------------------------

PANEL_MISSING = ("the panel's contract is not there: window.shadelab is undefined (app/web/src/start.js "
                 "sets it); issue 29: window.shadelab = {ready, state(), apply(), readPixels(), "
                 "describe (sl_describe's object, or a function returning it), frames, lastError}")


class PanelTest(PageTest):
    def open(self, query=""):
        load_page(DRIVER, query)
        self.assertTrue(DRIVER.execute_script("return window.shadelab !== undefined"), PANEL_MISSING)
        wait_for(DRIVER, "return window.shadelab.ready === true", "shadelab.ready")

    def state(self):
        return DRIVER.execute_script("return window.shadelab.state();")

    def option(self, name, state=None):
        """The value of --name in the panel's state (the last one), True for a flag, None if absent."""
        state = self.state() if state is None else state
        value = None
        for i, a in enumerate(state):
            if a == "--" + name:
                value = state[i + 1] if i + 1 < len(state) and not state[i + 1].startswith("--") else True
        return value

    def frames(self):
        return DRIVER.execute_script("return window.shadelab.frames;")

    def query(self):
        return urllib.parse.parse_qs(urllib.parse.urlparse(DRIVER.current_url).query)

    def message(self):
        return DRIVER.execute_script(
            "const m = document.getElementById('message'); if (!m) return null;"
            "const s = getComputedStyle(m); const visible = !m.hidden && s.display !== 'none' && s.visibility !== 'hidden'"
            " && m.getBoundingClientRect().height > 0; return {text: m.textContent.trim(), visible: visible,"
            " role: m.getAttribute('role')};")

    def press(self, *keys):
        from selenium.webdriver.common.action_chains import ActionChains
        DRIVER.execute_script("document.getElementById('canvas').focus();")
        for k in keys:
            before = self.frames()
            ActionChains(DRIVER).send_keys(k).perform()
            try:
                wait_for(DRIVER, "return window.shadelab.frames > %d" % before, "a frame after a key", timeout=10)
            except AssertionError:
                pass  # a key that changes nothing draws nothing; the caller checks the state

    def choose_file(self, path):
        from selenium.webdriver.common.by import By
        field = DRIVER.find_element(By.CSS_SELECTOR, "input[name=file]")
        field.send_keys(path)

    def wait_message(self, timeout=15):
        end = time.time() + timeout
        while time.time() < end:
            m = self.message()
            if m and m["visible"] and m["text"]:
                return m
            time.sleep(0.1)
        self.fail("no visible #message within %ds (got %s)" % (timeout, self.message()))


class PanelContract(PanelTest):
    def test_api(self):
        self.open()
        kinds = DRIVER.execute_script(
            "const s = window.shadelab; return {ready: s.ready, state: Array.isArray(s.state()),"
            " apply: typeof s.apply, readPixels: typeof s.readPixels, frames: typeof s.frames,"
            " describe: typeof (typeof s.describe === 'function' ? s.describe() : s.describe), lastError: s.lastError === undefined ? 'undefined' : 'defined'};")
        self.assertEqual(kinds, {"ready": True, "state": True, "apply": "function", "readPixels": "function",
                                 "frames": "number", "describe": "object", "lastError": "defined"})
        pixels = DRIVER.execute_script("return window.shadelab.readPixels();")
        self.assertEqual(len(base64.b64decode(pixels["base64"])), pixels["width"] * pixels["height"] * 4)

    def test_form_elements(self):
        """Every control is a labelled form element named like its option, with its option's range."""
        self.open()
        missing = DRIVER.execute_script(
            "return arguments[0].filter(n => !document.querySelector('[name=\"' + n + '\"]'));",
            ["ke", "ka", "kd", "ks", "layout", "shading", "reflection", "fresnel", "show", "preset", "file",
             "formula", "overlays"])
        self.assertEqual(missing, [], "form elements missing")
        unlabelled = DRIVER.execute_script(
            "return [...document.querySelectorAll('input[name],select[name]')].filter(e => e.type !== 'hidden'"
            " && e.labels.length === 0 && !e.getAttribute('aria-label')).map(e => e.name);")
        self.assertEqual(unlabelled, [], "form elements without a <label>")
        for b in ("previous", "next", "screenshot", "record", "message", "title", "caption", "help"):
            self.assertTrue(DRIVER.execute_script("return document.getElementById(arguments[0]) !== null", b), "#" + b)
        self.assertEqual(self.message()["role"], "alert")

    def test_ke_slider(self):
        """Setting the k_e slider changes the state, the URL and the picture."""
        self.open("preset=6&size=" + SIZE)
        before = self.frames()
        DRIVER.execute_script(
            "const e = document.querySelector('[name=ke]'); const setter = Object.getOwnPropertyDescriptor("
            "HTMLInputElement.prototype, 'value').set; setter.call(e, e.max); e.dispatchEvent(new Event('input',"
            " {bubbles: true})); e.dispatchEvent(new Event('change', {bubbles: true}));")
        wait_for(DRIVER, "return window.shadelab.frames > %d" % before, "a frame after the slider")
        ke = float(self.option("ke"))
        self.assertGreater(ke, 1000, "k_e slider at its end (log scale up to 10000): --ke %s" % ke)
        self.assertIn("ke", self.query())


def native_parameters():
    """The parameter table of the native build (its Python module, beside --shadelab), or None."""
    folder = os.path.join(os.path.dirname(os.path.abspath(ARGS.shadelab)), "python")
    if not os.path.isdir(os.path.join(folder, "shadelab")):
        return None
    code = "import json, shadelab; print(json.dumps(shadelab.parameters()))"
    run = subprocess.run(["/usr/bin/python3", "-c", code], env=dict(os.environ, PYTHONPATH=folder),
                         capture_output=True, text=True)
    return json.loads(run.stdout) if run.returncode == 0 else None


class PanelParameters(PanelTest):
    """The page's controls read the program's parameter table (core/scene/parameters.hpp), the one the
    desktop panel's sliders read: labels, ranges, slider ranges and scales, sections; lights and meshes
    are written as options by the program (sl_light_option, sl_mesh_option)."""

    def describe(self):
        return DRIVER.execute_script("const d = window.shadelab.describe; return typeof d === 'function' ? d() : d;")

    def test_the_table_is_the_native_one(self):
        self.open()
        native = native_parameters()
        if native is None:
            self.skipTest("no Python module beside %s to read the native table from" % ARGS.shadelab)
        page = self.describe()["parameters"]
        keys = ("name", "option", "symbol", "label", "section", "slider", "scale")
        self.assertEqual([{k: p[k] for k in keys} for p in page], [{k: list(p[k]) if isinstance(p[k], tuple) else p[k]
                                                                   for k in keys} for p in native])

    def test_sliders_labels_and_sections_are_the_tables(self):
        self.open("panel-sections=shading,material,plots,camera,background")
        options = [o for o in self.describe()["options"] if o.get("parameter") and o.get("section")]
        self.assertGreaterEqual(len(options), 12)
        shown = DRIVER.execute_script("""
            return arguments[0].map(n => {
              const box = document.querySelector('#panel [name="' + n + '"]');
              if (!box) return null;
              const row = box.closest('.row'), slider = row.querySelector('input[type=range]');
              return {section: box.closest('details').dataset.section, label: row.querySelector('label').textContent.trim(),
                      min: box.min, max: box.max, type: box.type,
                      slider: slider ? [parseFloat(slider.min), parseFloat(slider.max)] : null};
            });""", [o["name"][2:] for o in options])
        for o, e in zip(options, shown):
            p, name = o["parameter"], o["name"]
            self.assertIsNotNone(e, name + ": no control")
            self.assertEqual(e["section"], p["section"], name)
            self.assertIn(p["label"], e["label"], name)
            if e["type"] != "number":
                continue  # a colour picker
            self.assertEqual([float(e["min"]), float(e["max"])], p["range"], name)
            slider = [math.log10(x) for x in p["slider"]] if p["scale"] == "log" else p["slider"]
            if name != "--anisotropy":
                self.assertEqual(len(e["slider"]), 2, name)
                for got, want in zip(e["slider"], slider):
                    self.assertAlmostEqual(got, want, places=6, msg=name)

    def test_lights_and_meshes_are_written_by_the_program(self):
        self.open("preset=6&size=" + SIZE + "&panel-sections=lights,mesh")
        DRIVER.execute_script("""
            const box = document.querySelector('fieldset[data-light="0"] [data-part=intensity]');
            box.value = '2.5'; box.dispatchEvent(new Event('change', {bubbles: true}));""")
        wait_for(DRIVER, "return window.shadelab.state().includes('--light')", "--light after an intensity change")
        light = self.option("light")
        self.assertIn(":intensity=2.5", light)
        scene = DRIVER.execute_script("return window.shadelab.apply(window.shadelab.state()).scene.lights[0];")
        self.assertEqual(scene["intensity"], 2.5)
        DRIVER.execute_script("""
            const type = document.querySelector('#section-mesh select:not([name])');
            type.value = 'torus'; type.dispatchEvent(new Event('change', {bubbles: true}));""")
        wait_for(DRIVER, "return window.shadelab.state().includes('--mesh')", "--mesh after a mesh type")
        torus = [p for p in self.describe()["parameters"] if p.get("mesh") == "torus"]
        self.assertEqual(self.option("mesh"), "torus:%d:%d" % (torus[0]["default"], torus[1]["default"]))


class PanelPlaylist(PanelTest):
    def test_next_reaches_every_preset(self):
        """#next from preset 1 reaches every lecture preset in order, each with its title."""
        from selenium.webdriver.common.by import By
        self.open("preset=1&size=" + SIZE)
        described = DRIVER.execute_script("const d = window.shadelab.describe;"
                                          "return (typeof d === 'function' ? d() : d).presets;")
        self.assertEqual(len(described), len(presets()))
        seen, previous = [], None
        for i, p in enumerate(described):
            if i:
                before = self.frames()
                DRIVER.find_element(By.ID, "next").click()
                wait_for(DRIVER, "return window.shadelab.frames > %d" % before, "a frame after #next")
            title = DRIVER.find_element(By.ID, "title").text.strip()
            self.assertEqual(title, p["title"], "preset %d" % (i + 1))
            state = self.state()
            self.assertTrue(any(os.path.basename(a) == os.path.basename(p["path"]) for a in state)
                            or str(self.option("preset", state)) == str(i + 1), "preset %d: state %s" % (i + 1, state))
            self.assertIsNone(DRIVER.execute_script("return window.shadelab.lastError || null;"), p["path"])
            shown = DRIVER.execute_script("return window.shadelab.readPixels();")
            rgba = base64.b64decode(shown["base64"])
            colours = {rgba[i:i + 3] for i in range(0, len(rgba), 4 * 7)}
            self.assertGreaterEqual(len(colours), 3, "preset %d looks blank" % (i + 1))  # 11: ambient alone, flat colours
            self.assertNotEqual(rgba, previous, "preset %d shows what preset %d showed" % (i + 1, i))
            previous = rgba
            seen.append(title)
        self.assertEqual(len(set(seen)), len(presets()))
        DRIVER.find_element(By.ID, "previous").click()
        wait_for(DRIVER, "return document.getElementById('title').textContent.trim() === arguments[0]"
                 .replace("arguments[0]", json.dumps(described[-2]["title"])), "#previous")


class PanelFiles(PanelTest):
    console_errors_expected = True  # a refused file may also be logged

    def test_glb_through_file_input(self):
        self.open("size=" + SIZE)
        _, _, before = page_pixels()
        path = os.path.join(WORK, "checker_globe.glb")
        open(path, "wb").write(pack_glb(os.path.join(MODEL_DIR, "checker_globe.gltf")))
        frames = self.frames()
        self.choose_file(path)
        wait_for(DRIVER, "return window.shadelab.frames > %d" % frames, "a frame after the .glb")
        self.assertIsNone(DRIVER.execute_script("return window.shadelab.lastError || null;"))
        self.assertTrue(any("checker_globe.glb" in a for a in self.state()), self.state())
        _, _, after = page_pixels()
        self.assertNotEqual(before, after)
        m = self.message()
        self.assertFalse(m["visible"] and m["text"], "a message after a good file: %s" % m)

    def test_broken_file_keeps_drawing(self):
        self.open("preset=6&size=" + SIZE)
        _, _, before = page_pixels()
        path = os.path.join(WORK, "broken.gltf")
        open(path, "w").write('{"asset": {"version": "2.0"}, "meshes": [')
        self.choose_file(path)
        m = self.wait_message()
        self.assertIn("broken.gltf", m["text"])
        self.assertNotIn("\n", m["text"])
        _, _, after = page_pixels()
        self.assertEqual(before, after, "the picture changed after a broken file")
        frames = self.frames()
        self.press("w")
        wait_for(DRIVER, "return window.shadelab.frames > %d" % frames, "a frame after the broken file", timeout=10)

    def test_compressed_refused(self):
        for extension in ("KHR_draco_mesh_compression", "EXT_meshopt_compression"):
            self.open("preset=6")
            path = os.path.join(WORK, "compressed-%s.gltf" % extension[:5])
            open(path, "w").write(compressed_gltf(extension))
            self.choose_file(path)
            m = self.wait_message()
            self.assertIn(extension, m["text"])


class PanelRefinement(PanelTest):
    """An area light's sum refines to the end while the page is idle, as the desktop viewer's does, and a
    preset after another shows its own complete picture (preset 21's soft shadow, not 20's steps)."""

    def complete(self, what):
        wait_for(DRIVER, "return window.shadelab.ready && window.shadelab.progress === null", what, timeout=120)

    def test_area_lights_refine_to_the_end(self):
        presets = [p["name"] for p in self.open_and_describe()["presets"]]
        twenty = 1 + next(i for i, n in enumerate(presets) if n.startswith("20-"))
        self.open("preset=%d&size=%s" % (twenty, SIZE))
        self.complete("preset %d's passes all drawn, with nothing happening" % twenty)
        # The next preset, reached from this one as a lecturer steps through them: its first frame is
        # a first pass (progress set again), and then it too refines to the end.
        frames = self.frames()
        DRIVER.execute_script("document.getElementById('next').click();")
        wait_for(DRIVER, "return window.shadelab.frames > %d && window.shadelab.state()[0].includes('/%s')"
                 % (frames, presets[twenty]), "preset %d's first frame" % (twenty + 1))
        self.complete("preset %d's passes all drawn, with nothing happening" % (twenty + 1))
        self.assertGreater(self.frames() - frames, 2, "preset %d was refined over several frames" % (twenty + 1))
        frames = self.frames()
        time.sleep(1.0)
        self.assertEqual(self.frames(), frames, "a complete, idle page draws nothing")

    def open_and_describe(self):
        self.open("size=" + SIZE)
        return DRIVER.execute_script("const d = window.shadelab.describe; return typeof d === 'function' ? d() : d;")


class PanelViews(PanelTest):
    """What the panel shows besides the canvas: the help, the probe, the plots, the downloads, a drop."""

    def visible(self, element_id):
        return DRIVER.execute_script(
            "const e = document.getElementById(arguments[0]); return !!e && !e.hidden &&"
            " e.getBoundingClientRect().height > 0;", element_id)

    def test_help_is_the_key_table(self):
        from selenium.webdriver.common.keys import Keys
        self.open("size=" + SIZE)
        self.assertFalse(self.visible("help"))
        self.press(Keys.F1)
        self.assertTrue(self.visible("help"), "F1 opens the help")
        text = DRIVER.execute_script("return document.getElementById('help').textContent;")
        controls = DRIVER.execute_script("const d = window.shadelab.describe; return (typeof d === 'function' ? d() : d).controls;")
        for c in controls:  # every row of the key table, by its action (core/ui/controls.hpp)
            self.assertIn(c["action"], text)
        self.press(Keys.ESCAPE)
        self.assertFalse(self.visible("help"), "Esc closes the help")

    def test_click_probes_and_esc_clears(self):
        from selenium.webdriver.common.action_chains import ActionChains
        from selenium.webdriver.common.by import By
        from selenium.webdriver.common.keys import Keys
        self.open("preset=6&size=" + SIZE)
        _, _, before = page_pixels()
        frames = self.frames()
        ActionChains(DRIVER).move_to_element(DRIVER.find_element(By.ID, "canvas")).click().perform()
        wait_for(DRIVER, "return window.shadelab.frames > %d" % frames, "a frame after the probe click")
        self.assertTrue(self.visible("probe"), "a click on the model shows the probe")
        text = DRIVER.execute_script("return document.getElementById('probe').textContent;")
        for field in ("N", "V", "diffuse", "specular"):
            self.assertIn(field, text)
        _, _, probed = page_pixels()
        self.assertNotEqual(before, probed, "the probe's arrows are drawn")
        self.press(Keys.ESCAPE)
        self.assertFalse(self.visible("probe"), "Esc clears the probe")
        _, _, cleared = page_pixels()
        self.assertEqual(before, cleared, "the arrows go with the probe")

    def plot_pixels(self):
        return DRIVER.execute_script(
            "return [...document.querySelectorAll('canvas[data-plot]')].map(c => {"
            " const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;"
            " let h = 0; for (let i = 0; i < d.length; i += 97) h = (h * 31 + d[i]) | 0;"
            " return [c.dataset.plot, c.width, h]; });")

    def test_plots_follow_the_exponent(self):
        self.open("preset=6&size=" + SIZE + "&panel-sections=plots")
        first = self.plot_pixels()
        kinds = DRIVER.execute_script("const d = window.shadelab.describe; return (typeof d === 'function' ? d() : d).plots;")
        self.assertEqual(sorted(k for k, _, _ in first), sorted(kinds), "one canvas per plot of the table")
        self.assertIn("lobe", kinds)
        self.assertTrue(all(w > 0 for _, w, _ in first), first)
        DRIVER.execute_script("window.shadelab.apply(['%s/06-exponent-32.json', '--ke', '256', '--size', '%s']);"
                              % (PAGE_PRESET_DIR, SIZE))
        wait_for(DRIVER, "return true", "")
        time.sleep(0.5)
        after = dict((k, h) for k, _, h in self.plot_pixels())
        before = dict((k, h) for k, _, h in first)
        for kind in ("lobe", "lobe3d"):
            if kind in before:
                self.assertNotEqual(before[kind], after[kind], "the %s plot follows k_e" % kind)

    def downloads(self):
        return DRIVER.execute_script("return window.__downloads;")

    def catch_downloads(self):
        # The page downloads through an <a download> it clicks: recorded here instead of saved.
        DRIVER.execute_script(
            "window.__downloads = []; HTMLAnchorElement.prototype.click = function () {"
            " const a = this; fetch(a.href).then(r => r.blob()).then(b => window.__downloads.push("
            "{name: a.download, type: b.type, size: b.size})); };")

    def test_screenshot_and_record_buttons(self):
        from selenium.webdriver.common.by import By
        self.open("preset=6&size=" + SIZE)
        self.catch_downloads()
        DRIVER.find_element(By.ID, "screenshot").click()
        wait_for(DRIVER, "return window.__downloads.length === 1", "the screenshot's download")
        shot = self.downloads()[0]
        self.assertTrue(shot["name"].endswith(".png"), shot)
        self.assertEqual(shot["type"], "image/png")
        self.assertGreater(shot["size"], 1000)
        DRIVER.find_element(By.ID, "record").click()
        time.sleep(1.5)
        DRIVER.find_element(By.ID, "record").click()
        wait_for(DRIVER, "return window.__downloads.length === 2", "the recording's download", timeout=20)
        video = self.downloads()[1]
        self.assertTrue(video["name"].endswith(".webm"), video)
        self.assertTrue(video["type"].startswith("video/webm"), video)
        self.assertGreater(video["size"], 0)

    def test_drop_a_model(self):
        self.open("size=" + SIZE)
        _, _, before = page_pixels()
        data = base64.b64encode(pack_glb(os.path.join(MODEL_DIR, "lowpoly_gem.gltf"))).decode()
        frames = self.frames()
        DRIVER.execute_script(
            "const bytes = Uint8Array.from(atob(arguments[0]), c => c.charCodeAt(0));"
            "const t = new DataTransfer(); t.items.add(new File([bytes], 'gem.glb'));"
            "for (const type of ['dragenter', 'dragover', 'drop'])"
            " document.getElementById('canvas').dispatchEvent(new DragEvent(type, {dataTransfer: t, bubbles: true, cancelable: true}));",
            data)
        wait_for(DRIVER, "return window.shadelab.frames > %d" % frames, "a frame after the drop")
        self.assertTrue(any("gem.glb" in a for a in self.state()), self.state())
        self.assertIsNone(DRIVER.execute_script("return window.shadelab.lastError || null;"))
        _, _, after = page_pixels()
        self.assertNotEqual(before, after)


class PanelKeys(PanelTest):
    def test_keys(self):
        """The key table's keys change the state and the URL as the desktop viewer's do."""
        self.open("preset=6&layout=compare&size=" + SIZE)
        self.press("3")
        self.assertEqual((self.option("layout"), self.option("shading")), ("single", "phong"), self.state())
        self.press("c")
        self.assertEqual(self.option("layout"), "compare")
        self.assertEqual(self.query().get("layout"), ["compare"])
        self.press("d")
        self.assertEqual(self.option("layout"), "diff")
        self.assertEqual(self.query().get("layout"), ["diff"])
        self.press("w")
        self.assertIn("wireframe", str(self.option("overlays")))
        formula = self.option("formula")
        self.press("e")
        self.assertNotEqual(self.option("formula"), formula, "E toggles --formula")
        title = DRIVER.execute_script("return document.getElementById('title').textContent;")
        from selenium.webdriver.common.keys import Keys
        self.press(Keys.PAGE_DOWN)
        self.assertNotEqual(DRIVER.execute_script("return document.getElementById('title').textContent;"), title,
                            "Page Down goes to the next preset")
        self.assertEqual(self.query().get("preset"), ["7"])
        self.press(Keys.PAGE_UP)
        self.assertEqual(self.query().get("preset"), ["6"])


class PanelUrl(PanelTest):
    def test_round_trip(self):
        """A link carries the state: the options in the URL, the same state and pixels when it is opened."""
        self.open("preset=6&layout=compare&ke=128&shading=phong&size=" + SIZE)
        self.assertEqual(self.option("layout"), "compare")
        self.assertEqual(float(self.option("ke")), 128)
        self.assertEqual(self.option("size"), SIZE)
        DRIVER.execute_script("return window.shadelab.apply(['%s/06-exponent-32.json', '--layout', 'diff', '--ke', '64',"
                              " '--light', 'point:3,4,5', '--light', 'point:-3,4,5', '--size', '%s']);" % (PAGE_PRESET_DIR, SIZE))
        url = DRIVER.current_url
        q = self.query()
        self.assertEqual(q.get("layout"), ["diff"])
        self.assertEqual(len(q.get("light", [])), 2, "repeated light= parameters: %s" % url)
        state = self.state()
        _, _, pixels = page_pixels()
        load_page(DRIVER, url=url)
        self.assertEqual(self.state(), state)
        _, _, again = page_pixels()
        self.assertEqual(again, pixels)
        self.assertEqual(DRIVER.execute_script("const c = document.getElementById('canvas'); return [c.width, c.height];"),
                         [int(v) for v in SIZE.split("x")])


# --- SourceSize: the page's JavaScript in small parts (issue 40) ---------------------------------

class SourceSize(unittest.TestCase):
    """tests/web/js_size.py over app/web/src: functions of at most 40 lines, files of at most 400."""

    def setUp(self):
        sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
        import js_size
        self.js_size = js_size

    def test_page_sources(self):
        problems, longest = self.js_size.check([os.path.join(ROOT, "app", "web", "src")])
        self.assertEqual(problems, [], "\n".join(problems))
        self.assertIsNotNone(longest, "no function found in app/web/src")

    def test_the_check_fails(self):
        """A 41-line function, one nested in a method and a 401-line file are each caught."""
        body = "".join("  x += %d;\n" % i for i in range(39))
        cases = {"long.js": ("function long(x) {\n" + body + "}\n", ["long is 41 lines"]),
                 "nested.js": ("const o = {\n  update() {\n    const f = (a) => {\n" + body + "    };\n  },\n};\n",
                               ["f => is 41 lines", "update is 43 lines"]),
                 "big.js": ("// a line\n" * 401, ["401 lines (at most 400 a file)"])}
        for name, (text, said) in cases.items():
            path = os.path.join(WORK or tempfile.gettempdir(), name)
            with open(path, "w") as f:
                f.write(text)
            problems, _ = self.js_size.check([path])
            self.assertEqual(len(problems), len(said), "%s: %s" % (name, problems))
            for p, s in zip(problems, said):
                self.assertIn(s, p)
        short = os.path.join(WORK or tempfile.gettempdir(), "short.js")
        with open(short, "w") as f:
            f.write("function short(x) {\n" + body[:-len("  x += 38;\n")] + "}\n")
        self.assertEqual(self.js_size.check([short])[0], [])


# --- the runner ---------------------------------------------------------------------------------

def main():
    global ARGS, DRIVER, WORK
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--site", default=os.path.join(ROOT, "build-web"), help="the built page (./dev web)")
    parser.add_argument("--shadelab", default=os.path.join(ROOT, "build", "shadelab"),
                        help="the native program for the references (default build/shadelab: ./dev test builds it)")
    parser.add_argument("-k", action="append", default=[], metavar="PATTERN",
                        help="run only tests whose name contains PATTERN (repeatable)")
    parser.add_argument("--keep", metavar="DIR", help="keep the page's frames, references, diffs and screenshots in DIR")
    parser.add_argument("-v", "--verbose", action="store_true", help="name each test and print every comparison")
    ARGS = parser.parse_args()
    if not os.path.isfile(os.path.join(ARGS.site, "index.html")):
        sys.exit("test_web.py: %s/index.html missing: build the page first (./dev web)" % ARGS.site)
    if not os.access(ARGS.shadelab, os.X_OK):
        sys.exit("test_web.py: %s missing: the parity tests need the native program (./dev test builds it, "
                 "or give --shadelab PATH)" % ARGS.shadelab)
    if ARGS.keep:
        ARGS.keep = os.path.abspath(ARGS.keep)
    suite = unittest.defaultTestLoader.loadTestsFromModule(sys.modules[__name__])

    def tests(s):
        for t in s:
            if isinstance(t, unittest.TestSuite):
                yield from tests(t)
            else:
                yield t
    chosen = [t for t in tests(suite) if not ARGS.k or any(p.lower() in t.id().lower() for p in ARGS.k)]
    if not chosen:
        sys.exit("test_web.py: no test matches -k %s" % " ".join(ARGS.k))
    started = time.time()
    WORK = tempfile.mkdtemp(prefix="shadelab-web-")
    DRIVER = chromium()
    try:
        result = unittest.TextTestRunner(verbosity=2 if ARGS.verbose else 1).run(unittest.TestSuite(chosen))
    finally:
        DRIVER.quit()
        shutil.rmtree(WORK, ignore_errors=True)
    print("test_web.py: %d tests in %.0f s%s" % (result.testsRun, time.time() - started,
          ", images kept in " + ARGS.keep if ARGS.keep else ""), file=sys.stderr)
    sys.exit(0 if result.wasSuccessful() else 1)


if __name__ == "__main__":
    main()
