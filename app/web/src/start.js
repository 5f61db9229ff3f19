"use strict";  // esbuild keeps this directive at the top of the joined script (a classic script, not a module)
// Start: the test and embedding hook (window.shadelab), the page's start once the program runs,
// and the boot (this file is esbuild's entry point: the bundle runs boot() when it loads).
import { page, emptyState, argsOf, stateFromQuery } from "./state.js";
import { ccall, callJson, createProgram, failed, applyState, showError, note, requestFrame } from "./program.js";
import { buildPanel } from "./sections.js";
import { buildHelp, buildPlaylist, bindKeys } from "./keys.js";
import { bindDrop } from "./media.js";
import { layoutCanvas, bindPointer, probe, clearProbe } from "./view.js";

const $ = (selector) => document.querySelector(selector);

// ---------------------------------------------------------------------------------------------
// The hook. It stays on `window`, the page's one global, on purpose: tests/web/test_web.py and
// bench/web_bench.py (and a page that embeds shadelab) drive and read the page through it, from
// outside the bundle. ready, frames, lastError, probe, describe and module are values the page
// keeps up to date (page.hook); state(), apply(args), readPixels() and probeAt(x, y) act.
function installHook() {
  Object.assign(page.hook, {
    state: () => argsOf(page.state),
    apply: (args) => {
      const next = stateFromArgs((args || []).map(String));
      if (next.refused) return applyState(next.refused);  // the probe stays
      clearProbe();
      return applyState(next);
    },
    readPixels,
    probeAt: (x, y) => probe(x, y),
  });
  // describe: sl_describe(), an object, and also callable (shadelab.describe().presets);
  // module: the program (the emscripten module instance: ccall, HEAPU8, FS).
  window.shadelab = page.hook;
}
// A whole command line as a state: its first item, unless an option, is the input. An unknown
// option gives {refused}: a state of that option alone, which sl_apply() refuses with the program's
// message.
function stateFromArgs(list) {
  const next = emptyState();
  let i = 0;
  if (list.length && !list[0].startsWith("-")) {
    next.input = list[0];
    next.preset = page.D.presets.findIndex((p) => p.path === next.input) + 1;
    i = 1;
  }
  for (; i < list.length; i++) {
    const name = list[i].replace(/^--?/, "");
    const o = page.optionByName.get(name);
    if (!o) return { refused: { input: next.input, preset: next.preset, file: "", overrides: new Map([[name, true]]) } };
    if (!o.argument) next.overrides.set(name, true);
    else if (name === "light") next.overrides.set(name, (next.overrides.get(name) || []).concat([list[++i]]));
    else next.overrides.set(name, list[++i]);
  }
  return next;
}
function readPixels() {
  const r = callJson("sl_read_pixels");
  if (r.error) return r;
  const at = ccall("sl_frame_data", "number");
  const bytes = page.program.HEAPU8.subarray(at, at + r.width * r.height * 4);
  let text = "";
  for (let i = 0; i < bytes.length; i += 0x8000) text += String.fromCharCode.apply(null, bytes.subarray(i, i + 0x8000));
  return { width: r.width, height: r.height, base64: btoa(text) };
}

// ---------------------------------------------------------------------------------------------
// Start: the module is loaded and main() has made the WebGL2 context.
function start() {
  const gl = callJson("sl_gl_info");
  if (gl.error) {
    failed("this browser offers no WebGL2 (it is switched off, or the graphics driver is blocked: try another browser, or turn on hardware acceleration)");
    return;
  }
  const D = callJson("sl_describe");
  page.D = D;
  page.optionByName = new Map(D.options.map((o) => [o.name.replace(/^--/, ""), o]));
  page.hook.describe = Object.assign(() => D, D);
  note("");
  const fromLink = stateFromQuery(location.search);
  page.state = fromLink.state;
  if (page.state.overrides.has("hide-panel")) document.body.classList.add("panel-hidden");
  buildPlaylist();
  buildPanel();
  buildHelp();
  // The canvas's size before the first scene, so that it is framed for the view.
  const box = $("#view").getBoundingClientRect(), dpr = window.devicePixelRatio || 1;
  callJson("sl_resize", ["number", "number"], [Math.max(16, Math.round(box.width * dpr)), Math.max(16, Math.round(box.height * dpr))]);
  const r = applyLink(fromLink.problems);
  if (r.error) return;
  new ResizeObserver(() => layoutCanvas()).observe($("#view"));
  window.addEventListener("resize", layoutCanvas);
  requestFrame();
}
// The link's state; where its options are refused, its input without them, else the built-in scene.
function applyLink(problems) {
  const state = page.state;
  let r = applyState(state);
  if (r.error) {
    const message = "link: " + r.error;
    const plain = { input: state.input, preset: state.preset, file: "", overrides: new Map() };
    r = applyState(plain);
    if (r.error) r = applyState(emptyState());
    showError(message);
  }
  if (problems.length) showError("link: " + problems.join("; "));
  return r;
}

function boot() {
  installHook();
  window.addEventListener("error", (e) => {
    if (!page.hook.ready) failed(e.message || "an error in the page");
  });
  bindPointer();
  bindDrop();
  bindKeys();
  createProgram(start);
  if (!window.WebGL2RenderingContext) failed("this browser has no WebGL2");
}

boot();
