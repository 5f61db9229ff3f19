// The view: the canvas's size, the pane labels, the camera (pointer drags and the wheel over the
// canvas) and the probe (a click without a drag; the terms in a table over the view).
import { page } from "./state.js";
import { running, ccall, callJson, showError, requestFrame, drawFrame } from "./program.js";
import { el, fmt } from "./controls.js";

const $ = (selector) => document.querySelector(selector);
export const canvas = $("#canvas");

// ---------------------------------------------------------------------------------------------
// The canvas: its CSS size x devicePixelRatio is its pixel size unless --size pins it.
export function layoutCanvas() {
  const result = page.result;
  const box = $("#view").getBoundingClientRect();
  if (result && result.pinned) {
    // The pinned picture at one canvas pixel per CSS pixel (as the browser shows an image at
    // 100%), smaller where the view is.
    const scale = Math.min(1, box.width / result.width, box.height / result.height);
    canvas.style.width = (result.width * scale) + "px";
    canvas.style.height = (result.height * scale) + "px";
  } else {
    canvas.style.width = "100%";
    canvas.style.height = "100%";
    followView(box);
  }
  drawLabels();
  requestFrame();
}
// The canvas's pixel size from the view's box (CSS pixels x devicePixelRatio).
function followView(box) {
  const dpr = window.devicePixelRatio || 1;
  const w = Math.max(16, Math.round(box.width * dpr)), h = Math.max(16, Math.round(box.height * dpr));
  if (running() && (w !== canvas.width || h !== canvas.height)) {
    const r = callJson("sl_resize", ["number", "number"], [w, h]);
    if (r.panes && page.result) Object.assign(page.result, { panes: r.panes, width: r.width, height: r.height });
    if (page.probeAt) clearProbe();
    // A resized canvas is blank: drawn at once, before the browser shows it.
    if (page.hook.ready) drawFrame();
  }
}
// Canvas pixels per CSS pixel.
function canvasScale() {
  const rect = canvas.getBoundingClientRect();
  return rect.width > 0 ? canvas.width / rect.width : 1;
}

// Pane labels (flat / Gouraud / Phong, the difference) over each pane.
const MODE_LABEL = { flat: "flat", gouraud: "Gouraud", phong: "Phong" };
export function drawLabels() {
  const box = $("#labels");
  box.textContent = "";
  const result = page.result;
  if (!result || page.state.overrides.has("no-labels")) return;
  const s = canvasScale();
  const rect = canvas.getBoundingClientRect(), view = $("#view").getBoundingClientRect();
  const scene = result.scene;
  for (const p of result.panes) {
    const label = document.createElement("div");
    label.className = "pane-label";
    label.textContent = p.difference
      ? "|" + (MODE_LABEL[scene.diff.a] || scene.diff.a) + " \u2212 " + (MODE_LABEL[scene.diff.b] || scene.diff.b) + "| \u00d7 " + fmt(scene.diff.factor)
      : MODE_LABEL[p.mode] || p.mode;
    label.style.left = (rect.left - view.left + p.x / s) + "px";
    label.style.top = (rect.top - view.top + p.y / s) + "px";
    label.style.width = (p.width / s) + "px";
    box.appendChild(label);
  }
}

// ---------------------------------------------------------------------------------------------
// The probe: a click without a drag; the terms in a table over the view.
export function probe(x, y) {
  const p = callJson("sl_probe", ["number", "number"], [x, y]);
  if (p.error) {
    showError(p.error);
    return p;
  }
  page.probeAt = [x, y];
  showProbe(p);
  requestFrame();  // the formula overlay shows the probed values
  return p;
}
function vec(v) {
  if (Array.isArray(v)) return v.map((x) => (typeof x === "number" ? fmt(+x.toFixed(4)) : String(x))).join(", ");
  if (typeof v === "number") return fmt(+v.toFixed(5));
  if (v && typeof v === "object") return JSON.stringify(v);
  return String(v);
}
export function showProbe(p) {
  page.hook.probe = p;
  const box = $("#probe");
  box.textContent = "";
  const head = el("div", { class: "probe-head" });
  head.append(el("strong", { text: "probe " + p.pixel.join(", ") }));
  const close = el("button", { type: "button", class: "close", text: "\u00d7", "aria-label": "clear the probe (Esc)" });
  close.addEventListener("click", clearProbe);
  head.append(close);
  box.append(head);
  box.append(probeTable(p));
  box.hidden = false;
  // The table on the other side of the view from the probed pixel.
  box.classList.toggle("left", p.pixel[0] > canvas.width / 2);
  const mark = $("#probe-mark");
  const s = canvasScale(), rect = canvas.getBoundingClientRect(), view = $("#view").getBoundingClientRect();
  mark.style.left = (rect.left - view.left + (p.pixel[0] + 0.5) / s) + "px";
  mark.style.top = (rect.top - view.top + (p.pixel[1] + 0.5) / s) + "px";
  mark.hidden = false;
}
// The probe's terms: a row a value, a group row per evaluation and per light.
function probeTable(p) {
  const table = el("table");
  const row = (k, v, cls) => table.append(el("tr", { class: cls }, el("th", { text: k }), el("td", { text: vec(v) })));
  const section = (text) => table.append(el("tr", { class: "group" }, el("th", { colspan: 2, text })));
  if (p.miss) {
    row("miss", true);
    for (const k of ["background", "output_8bit"]) if (p[k] !== undefined) row(k, p[k]);
    return table;
  }
  for (const k of ["mode", "object", "output_8bit", "output", "color"]) if (p[k] !== undefined) row(k, p[k]);
  if (p.material) for (const [k, v] of Object.entries(p.material)) row(k, v);
  for (const e of p.evaluations || []) {
    section("at " + e.at + (e.vertex !== undefined ? " " + e.vertex : "") + (e.weight !== undefined ? "  (weight " + fmt(+e.weight.toFixed(4)) + ")" : ""));
    for (const [k, v] of Object.entries(e)) {
      if (k === "lights" || k === "at" || k === "vertex" || k === "weight") continue;
      row(k, v, ["ambient", "diffuse", "specular", "sum", "total"].includes(k) ? "term " + k : "");
    }
    for (const l of e.lights || []) {
      section("light " + l.light + (l.type ? " (" + l.type + ")" : ""));
      for (const [k, v] of Object.entries(l)) if (k !== "light" && k !== "type") row(k, v, k === "diffuse" || k === "specular" ? "term " + k : "");
    }
  }
  return table;
}
export function clearProbe() {
  if (!page.probeAt && $("#probe").hidden) return;
  page.probeAt = null;
  page.hook.probe = null;
  if (running()) ccall("sl_clear_probe", null);
  $("#probe").hidden = true;
  $("#probe-mark").hidden = true;
  requestFrame();
}

// ---------------------------------------------------------------------------------------------
// The camera: pointer drags and the wheel over the canvas.
export function camera(what) {
  ccall("sl_camera", null, ["string"], [what]);
  clearProbe();
  requestFrame();
}
const DRAG_THRESHOLD = 4;  // CSS pixels before a press is a drag, not a click
function pointerDown(e) {
  if (!running()) return;
  canvas.focus({ preventScroll: true });
  canvas.setPointerCapture(e.pointerId);
  page.drag = { id: e.pointerId, button: e.button, x: e.clientX, y: e.clientY, startX: e.clientX, startY: e.clientY, moved: false };
  e.preventDefault();
}
function pointerMove(e) {
  const drag = page.drag;
  if (!drag || e.pointerId !== drag.id) return;
  const dx = e.clientX - drag.x, dy = e.clientY - drag.y;
  if (!drag.moved && Math.hypot(e.clientX - drag.startX, e.clientY - drag.startY) < DRAG_THRESHOLD) return;
  if (!drag.moved) clearProbe();
  drag.moved = true;
  drag.x = e.clientX;
  drag.y = e.clientY;
  if (drag.button === 0) {
    // CSS pixels: the same turn per hand movement as the desktop viewer at any device scale.
    ccall("sl_orbit", null, ["number", "number"], [dx, dy]);
  } else {
    // Canvas pixels: the model follows the pointer.
    const s = canvasScale();
    ccall("sl_pan", null, ["number", "number"], [dx * s, dy * s]);
  }
  requestFrame();
}
function endDrag(e) {
  if (!page.drag || e.pointerId !== page.drag.id) return;
  const d = page.drag;
  page.drag = null;
  if (e.type === "pointerup" && !d.moved && d.button === 0) {
    const rect = canvas.getBoundingClientRect(), s = canvasScale();
    const x = Math.floor((e.clientX - rect.left) * s), y = Math.floor((e.clientY - rect.top) * s);
    if (x >= 0 && y >= 0 && x < canvas.width && y < canvas.height) probe(x, y);
  }
}
function wheel(e) {
  if (!running()) return;
  e.preventDefault();
  // One notch (100 pixels, or 3 lines) is one step; forward (deltaY < 0) zooms in, as the desktop wheel.
  const steps = -e.deltaY / (e.deltaMode === 1 ? 3 : e.deltaMode === 2 ? 1 : 100);
  ccall("sl_zoom", null, ["number"], [steps]);
  clearProbe();
  requestFrame();
}
export function bindPointer() {
  canvas.addEventListener("pointerdown", pointerDown);
  canvas.addEventListener("pointermove", pointerMove);
  canvas.addEventListener("pointerup", endDrag);
  canvas.addEventListener("pointercancel", endDrag);
  canvas.addEventListener("contextmenu", (e) => e.preventDefault());
  canvas.addEventListener("wheel", wheel, { passive: false });
}
