// The program bridge: the emscripten module (web_app.cpp built with -sMODULARIZE=1
// -sEXPORT_NAME=createShadelab: index.js defines that factory and no `Module`), its sl_* functions,
// applying a state, the frames, and the page's messages.
import { page, argsOf, cloneState, dropSceneOptions, followAddress } from "./state.js";
import { refreshPanel, drawPlots } from "./sections.js";
import { canvas, layoutCanvas, drawLabels, clearProbe, showProbe } from "./view.js";

const $ = (selector) => document.querySelector(selector);

// ---------------------------------------------------------------------------------------------
// The program's functions.
export function running() {
  return !!(page.program && page.program.calledRun);
}
export function ccall(name, returns, types, args) {
  return page.program.ccall(name, returns, types || [], args || []);
}
export function call(name, types, args) {
  return ccall(name, "string", types, args);
}
export function callJson(name, types, args) {
  return JSON.parse(call(name, types, args));
}

// Makes the program: `start` runs once main() has made the WebGL2 context.
export function createProgram(start) {
  const settings = {
    canvas,
    print: (text) => console.log(text),
    printErr: (text) => {
      console.warn(text);
      if (/^shadelab: warning: /.test(text)) page.warnings.push(text.replace(/^shadelab: /, ""));
      else if (/^shadelab: /.test(text)) showError(text.replace(/^shadelab: /, ""));
    },
    onAbort: (what) => failed("the program stopped (" + what + ")"),
    postRun: [start],
  };
  // The object given to the factory is the module instance it fills (ccall, HEAPU8, calledRun ...).
  page.program = settings;
  page.hook.module = settings;
  if (typeof createShadelab !== "function") return failed("the program (index.js) could not be loaded");
  createShadelab(settings);  // index.js's factory; it returns a promise of the same object
}

// ---------------------------------------------------------------------------------------------
// Messages: #message (role=alert) holds an error in one line; #note a passing remark.
// A line where the page cannot start (the program missing, no WebGL2): never a blank page.
export function failed(text) {
  const m = document.getElementById("message");
  m.textContent = "shadelab cannot start: " + text;
  m.hidden = false;
  const n = document.getElementById("note");
  if (n) n.hidden = true;
  document.body.classList.add("failed");
  page.hook.lastError = m.textContent;
}
export function showError(text) {
  const m = $("#message");
  m.textContent = text;
  m.hidden = !text;
  page.hook.lastError = text || "";
}
export function note(text, seconds) {
  const n = $("#note");
  n.textContent = text;
  n.hidden = !text;
  clearTimeout(page.noteTimer);
  if (text && seconds) page.noteTimer = setTimeout(() => { n.hidden = true; }, seconds * 1000);
}

// ---------------------------------------------------------------------------------------------
// Applies a state: on success it is the page's, else the message says why and nothing changes.
export function applyState(next) {
  const r = callJson("sl_apply", ["string"], [JSON.stringify(argsOf(next))]);
  if (r.error) {
    showError(r.error);
    if (page.result) refreshPanel();  // the controls show the state still drawn
    return r;
  }
  page.state = next;
  page.result = r;
  showError("");
  const said = (r.warnings || []).concat(page.warnings.splice(0));
  if (said.length) note("warning: " + said.join("; "), 10);
  afterApply();
  return r;
}
export function setOverride(name, value) {
  const next = cloneState(page.state);
  if (value === null || value === undefined) next.overrides.delete(name);
  else next.overrides.set(name, value);
  if (name === "shadows") next.overrides.delete("no-shadows");
  if (name === "no-shadows") next.overrides.delete("shadows");
  return applyState(next);
}
export function choosePreset(n) {
  const D = page.D;
  if (!D.presets.length) return;
  n = Math.max(1, Math.min(D.presets.length, n));
  const next = cloneState(page.state);
  dropSceneOptions(next);
  next.preset = n;
  next.input = D.presets[n - 1].path;
  next.file = "";
  clearProbe();
  applyState(next);
}
function afterApply() {
  if (page.probeAt) {
    const p = callJson("sl_probe", ["number", "number"], page.probeAt);
    if (p.error) clearProbe();
    else showProbe(p);
  }
  refreshPanel();
  followAddress();
  layoutCanvas();
  drawPlots();
  drawLabels();
  requestFrame();
}

// ---------------------------------------------------------------------------------------------
// Frames: drawn on the next animation frame when something changed, none while idle.
export function requestFrame() {
  if (page.framePending) return;
  page.framePending = true;
  requestAnimationFrame(() => {
    page.framePending = false;
    drawFrame();
  });
}
export function drawFrame() {
  const r = callJson("sl_render");
  if (r.error) showError(r.error);
  const hook = page.hook;
  hook.frames++;
  if (!hook.ready) {
    hook.ready = true;
    document.title = "shadelab \u2014 " + titleText();
  }
  // A sampled area light refines over frames, as in the desktop viewer: the next pass is asked for
  // until the sum is complete, also while nothing else happens (an idle page then draws nothing).
  hook.progress = r.progress || null;
  if (page.recorder || r.progress) requestFrame();  // the recording wants frames coming
}
export function titleText() {
  const { result, state, D } = page;
  if (!result) return "";
  if (result.title) return result.title;
  if (state.file) return state.file;
  if (state.preset) return D.presets[state.preset - 1].name;
  return "the built-in scene";
}
