#!/usr/bin/python3
"""The web page's figures (bench/README.md, "Web page"): build-web/'s size, the time to the first
frame in headless chromium, the frame time of the default compare view at 1280x720 (SwiftShader)
against `shadelab --benchmark` (llvmpipe), and optionally the build's time.

    /usr/bin/python3 bench/web_bench.py [--site build-web] [--shadelab build/shadelab] [--rounds 5]
                                        [--frames 50] [--build] [--no-ccache]

--build first removes build-web-cmake/ and times `./dev web` (ccache as it is; with --no-ccache,
CCACHE_DISABLE=1, into a separate folder so build-web-cmake's cache stays warm).
Needs Debian's python3-selenium, chromium and chromium-driver (third_party/packages-web.txt).
"""
import argparse
import json
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.dont_write_bytecode = True  # no __pycache__ in the checkout
sys.path.insert(0, os.path.join(ROOT, "tests", "web"))
import test_web  # noqa: E402  (the browser's options and the page's readiness, shared with the tests)

FRAME_TIMES = """
const n = arguments[0], warm = 3;
const Module = window.shadelab.module;
// The program's WebGL2 context: getContext gives the canvas's existing one (index.js keeps its GLctx
// to itself, -sMODULARIZE).
const GLctx = document.getElementById('canvas').getContext('webgl2');
const finish = () => {
  // A 1x1 read waits for the frame to be drawn (gl.finish alone need not, in Chromium).
  if (GLctx) GLctx.readPixels(0, 0, 1, 1, GLctx.RGBA, GLctx.UNSIGNED_BYTE, new Uint8Array(4));
  else Module.ccall('sl_read_pixels', 'string', [], []);
};
const times = [];
for (let i = 0; i < warm + n; ++i) {
  const t = performance.now();
  const r = JSON.parse(Module.ccall('sl_render', 'string', [], []));
  if (r.error) return {error: r.error};
  finish();
  if (i >= warm) times.push(performance.now() - t);
}
return {times: times, finisher: GLctx ? 'GLctx.readPixels 1x1' : 'sl_read_pixels'};
"""


def first_frame_ms(query):
    """ms from navigation start to the first frame: polled every 10 ms (the page marks its first
    frame by document.title = 'shadelab ready' or shadelab.ready), so at most ~15 ms late."""
    driver = test_web.chromium()
    try:
        start = time.time()
        driver.get(test_web.site_url(query))
        while True:
            t = driver.execute_script(
                "return (document.title === 'shadelab ready' || (window.shadelab && window.shadelab.ready === true))"
                " ? performance.now() : null;")
            if t is not None:
                return t, (time.time() - start) * 1000
            if time.time() - start > 60:
                raise RuntimeError("no first frame within 60 s")
            time.sleep(0.01)
    finally:
        driver.quit()


def page_frames(frames, msaa):
    driver = test_web.chromium()
    try:
        test_web.load_page(driver, "size=1280x720")
        r = test_web.apply(["--layout", "compare", "--size", "1280x720", "--msaa", str(msaa)], driver)
        if "error" in r:
            raise RuntimeError(r["error"])
        out = driver.execute_script(FRAME_TIMES, frames)
        if "error" in out:
            raise RuntimeError(out["error"])
        return out["times"], out["finisher"]
    finally:
        driver.quit()


def native_frames(shadelab, frames, msaa):
    r = subprocess.run([shadelab, "--layout", "compare", "--size", "1280x720", "--benchmark", str(frames),
                        "--msaa", str(msaa)], capture_output=True, text=True, check=True)
    return json.loads(r.stdout.strip().splitlines()[-1])


def time_build(no_ccache):
    env = dict(os.environ)
    cmd = ["./dev", "web"]
    if no_ccache:
        folder = tempfile.mkdtemp(prefix="shadelab-web-nocache-")
        env.update(CCACHE_DISABLE="1", BUILD_DIR=os.path.join(folder, "cmake"),
                   CMAKE_ARGS="-DSHADELAB_WEB_SITE=" + os.path.join(folder, "site"))
    else:
        shutil.rmtree(os.path.join(ROOT, "build-web-cmake"), ignore_errors=True)
    start = time.time()
    subprocess.run(cmd, cwd=ROOT, env=env, check=True, stdout=subprocess.DEVNULL)
    took = time.time() - start
    if no_ccache:
        shutil.rmtree(folder, ignore_errors=True)
    return took


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--site", default=os.path.join(ROOT, "build-web"))
    p.add_argument("--shadelab", default=os.path.join(ROOT, "build", "shadelab"))
    p.add_argument("--rounds", type=int, default=5)
    p.add_argument("--frames", type=int, default=50)
    p.add_argument("--build", action="store_true", help="also time ./dev web from an empty build-web-cmake/")
    p.add_argument("--no-ccache", action="store_true", help="with --build: CCACHE_DISABLE=1")
    args = p.parse_args()
    test_web.ARGS = argparse.Namespace(site=args.site)

    if args.build:
        print("./dev web from an empty build folder%s: %.0f s" % (
            " (CCACHE_DISABLE=1)" if args.no_ccache else " (ccache as it is)", time_build(args.no_ccache)))

    size = sum(os.path.getsize(os.path.join(d, f)) for d, _, fs in os.walk(args.site) for f in fs)
    print("build-web/: %d bytes (%.2f MiB; limit 8 MiB)" % (size, size / 2**20))
    for f in sorted(os.listdir(args.site)):
        print("  %-12s %9d" % (f, os.path.getsize(os.path.join(args.site, f))))

    firsts = [first_frame_ms("") for _ in range(args.rounds)]
    page = [f[0] for f in firsts]
    print("first frame, performance.now() from navigation start (the page opened without parameters): median %.0f ms "
          "(%.0f-%.0f) over %d loads; driver.get to first frame seen: median %.0f ms" % (
              statistics.median(page), min(page), max(page), len(page), statistics.median(f[1] for f in firsts)))

    print("| msaa | page (SwiftShader) median ms (min-max of round medians), p95 | shadelab --benchmark (llvmpipe) median ms, p95 | page / native |")
    print("| --- | --- | --- | --- |")
    for msaa in (1, 4):
        medians, p95s, natives, native95 = [], [], [], []
        finisher = ""
        for _ in range(args.rounds):
            times, finisher = page_frames(args.frames, msaa)
            times.sort()
            medians.append(statistics.median(times))
            p95s.append(times[int(0.95 * (len(times) - 1))])
            n = native_frames(args.shadelab, args.frames, msaa)
            natives.append(n["median_ms"])
            native95.append(n["p95_ms"])
        print("| %d | %.1f (%.1f-%.1f), %.1f | %.1f (%.1f-%.1f), %.1f | %.1f |" % (
            msaa, statistics.median(medians), min(medians), max(medians), statistics.median(p95s),
            statistics.median(natives), min(natives), max(natives), statistics.median(native95),
            statistics.median(medians) / statistics.median(natives)))
    print("(page: %d frames of sl_render + %s after 3 warm-up frames, per round; compare layout, "
          "default scene, 1280x720; %d rounds, page and native alternating)" % (args.frames, finisher, args.rounds))


if __name__ == "__main__":
    main()
