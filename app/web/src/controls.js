// The panel's controls, generated from the option table (sl_describe().options): a parameter's option
// (k_a ... k_e, the ior, the incidence, the colours) shows its parameter's label, slider range and
// scale, decimals and default from the program's parameter table (core/scene/parameters.hpp), the
// desktop panel's; and the small kit they are made with (el, labelled, fmt, the colour conversions).
//
// Hand-written, not a widget library (lil-gui and the like): each control is made from the option
// table's row with its exact name (name="ke", which the tests and the link use), its label, its help
// text as `title` and an accessible <label for>; a library would build its own rows, names and
// labels, and the controls here are few and small.
import { page, cloneState, shownValue } from "./state.js";
import { setOverride, applyState } from "./program.js";

// ---------------------------------------------------------------------------------------------
// Formatting and elements.
export function fmt(x) {
  if (typeof x !== "number") return String(x);
  if (!isFinite(x)) return String(x);
  const r = Math.abs(x) >= 1e-3 || x === 0 ? +x.toPrecision(5) : +x.toPrecision(3);
  return String(r);
}
export function fmtList(a) { return a.map(fmt).join(","); }
export function el(tag, attributes, ...children) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attributes || {})) {
    if (v === undefined || v === null || v === false) continue;
    if (k === "text") e.textContent = v;
    else if (k === "class") e.className = v;
    else e.setAttribute(k, v === true ? "" : v);
  }
  for (const c of children) if (c) e.append(c);
  return e;
}
function newId() {
  return "c" + (++page.uid);
}
export function labelled(text, input, help) {
  if (!input.id) input.id = newId();
  const row = el("div", { class: "row" }, el("label", { for: input.id, text: text, title: help || undefined }), input);
  return row;
}
export function hex(rgb) {
  return "#" + rgb.map((c) => Math.round(Math.max(0, Math.min(1, c)) * 255).toString(16).padStart(2, "0")).join("");
}
export function rgbOf(hexText) {
  return [1, 3, 5].map((i) => parseInt(hexText.substr(i, 2), 16) / 255);
}

// An option's choices ("flat | gouraud | phong").
export function namesOf(o) {
  return (o.names || "").split(/\s*(?:\||,|\bor\b)\s*/).filter((n) => n);
}
// How a number control's slider maps its travel (the parameter's slider range and scale; an option
// without a parameter: its range, linear) and how many decimals a value gets.
export function sliderOf(o) {
  const p = o.parameter;
  const [lo, hi] = p ? p.slider : o.range;
  const log = !!p && p.scale === "log";
  return {
    lo, hi, log, decimals: p ? p.decimals : 3,
    to: (v) => (log ? Math.log10(Math.max(lo, v)) : v),
    from: (t) => (log ? Math.pow(10, t) : t),
  };
}
function sliderInput(label, s) {
  const [a, b] = [s.to(s.lo), s.to(s.hi)];
  return el("input", { type: "range", "aria-label": label + (s.log ? " (logarithmic slider)" : " (slider)"), min: a, max: b, step: (b - a) / 1000 });
}

// Slider changes are applied once a frame, however fast the input events come.
// One that comes after the input changed (another preset, a file) is dropped.
function scheduleOverride(name, value) {
  const first = !page.pendingOverride;
  page.pendingOverride = [name, value, page.state.input];
  if (first) requestAnimationFrame(() => {
    const [n, v, input] = page.pendingOverride;
    page.pendingOverride = null;
    if (input === page.state.input) setOverride(n, v);
  });
}

// ---------------------------------------------------------------------------------------------
// The controls.
function choiceControl(o, names, fallback) {
  const name = o.name.slice(2);
  const select = el("select", { name });
  for (const n of names) select.append(el("option", { value: n, text: n }));
  select.addEventListener("change", () => setOverride(name, select.value));
  page.controls.push({
    update() {
      const v = String(shownValue(name, fallback));
      if (![...select.options].some((x) => x.value === v)) select.append(el("option", { value: v, text: v }));
      select.value = v;
    },
  });
  return labelled(name, select, o.help);
}
// A number of the option's range: a slider over the parameter's slider range (logarithmic for k_e)
// and a number box that takes the whole range. Unset, it shows the parameter's default.
export function numberControl(o) {
  const name = o.name.slice(2), p = o.parameter;
  const [lo, hi] = o.range;
  const s = sliderOf(o);
  const slider = sliderInput(name, s);
  const box = el("input", { type: "number", name, min: lo, max: hi, step: "any", class: "number" });
  slider.addEventListener("input", () => {
    let v = s.from(parseFloat(slider.value));
    v = s.log ? +v.toPrecision(3) : +v.toFixed(s.decimals);
    box.value = fmt(v);
    scheduleOverride(name, fmt(v));
  });
  box.addEventListener("change", () => setOverride(name, box.value === "" ? null : box.value.trim()));
  const fallback = p && p.default !== undefined ? p.default : undefined;
  page.controls.push({ update: () => showNumber(slider, box, s.to(s.lo), s.to, shownValue(name, fallback)) });
  const row = labelled(p ? p.label : name, box, o.help);
  row.classList.add("number-row");
  row.append(slider);
  return row;
}
// A number control shows v (the slider at `low` where it is unset).
function showNumber(slider, box, low, toSlider, v) {
  // Unset (a material's mirror or transmission): an empty box and the slider at its
  // low end, dimmed, until a value is given.
  const unset = v === undefined || v === "";
  slider.classList.toggle("unset", unset);
  if (unset) {
    box.value = "";
    slider.value = low;
    return;
  }
  const x = parseFloat(v);
  if (document.activeElement !== box) box.value = fmt(x);
  slider.value = toSlider(x);
}
export function switchControl(o, checkedOf, onChange) {
  const name = o.name.slice(2);
  const box = el("input", { type: "checkbox", name });
  box.addEventListener("change", () => onChange(box.checked));
  page.controls.push({ update() { box.checked = !!checkedOf(); } });
  const row = el("div", { class: "row check" }, el("label", { title: o.help }, box, " " + name));
  return row;
}
function simpleSwitch(o) {
  const name = o.name.slice(2);
  return switchControl(o, () => page.state.overrides.get(name) === true, (on) => setOverride(name, on ? true : null));
}
// --size WxH: a text box, empty while the canvas follows the window.
function sizeControl(o) {
  const name = "size";
  const box = el("input", { type: "text", name, placeholder: "follows the window", pattern: "\\d+x\\d+", class: "text", spellcheck: "false" });
  box.addEventListener("change", () => setOverride(name, box.value.trim() || null));
  page.controls.push({ update() { if (document.activeElement !== box) box.value = page.state.overrides.get(name) || ""; } });
  return labelled(name + " (pins WxH)", box, o.help);
}

// The control of an option (by its name without "--"), or null where the panel has none for it.
export function optionControl(name) {
  const o = page.optionByName.get(name);
  if (!o) return null;
  switch (name) {
    case "diff": {
      const modes = namesOf(o), pairs = [];
      for (const a of modes) for (const b of modes) if (a !== b) pairs.push(a + "," + b);
      return choiceControl(o, pairs);
    }
    case "show": return choiceControl(o, namesOf(o));  // light:N filled per scene in refreshPanel
    case "msaa": return choiceControl(o, namesOf(o), "4");  // web_app.cpp draws with 4 unless --msaa
    case "anisotropy": return anisotropyControl(o);
    case "shadows":
      return switchControl(o, () => page.result.scene.shadows === true, (on) => setOverride(on ? "shadows" : "no-shadows", true));
    case "size": return sizeControl(o);
  }
  if (o.parameter && o.parameter.components === 3) return colourControl(o);
  if (o.names && o.argument) return choiceControl(o, namesOf(o), "");
  if (o.range && o.argument) return numberControl(o);
  if (!o.argument) return simpleSwitch(o);
  return null;
}

// --anisotropy KT,KB: a switch and two logarithmic sliders (k_t along the tangent, k_b along the
// bitangent), as the desktop panel's. Off is no override: the scene's own (usually none). The
// lobe is Blinn-Phong's (the option needs --reflection blinn-phong): switched on, it asks for it.
function anisotropyControl(o) {
  const s = sliderOf(o), toSlider = s.to, fromSlider = (t) => +s.from(t).toPrecision(3), lo = s.lo;
  const on = el("input", { type: "checkbox", "aria-label": "anisotropy on" });
  const box = el("input", { type: "text", name: "anisotropy", class: "text", spellcheck: "false", placeholder: "KT,KB e.g. 8,256" });
  const sliders = o.parameter.parts.map((label) => sliderInput(label, s));
  on.addEventListener("change", () => setAnisotropy(on.checked ? [8, 256] : null));
  box.addEventListener("change", () => setAnisotropy(box.value.trim() ? box.value.trim().split(",").map(parseFloat) : null));
  sliders.forEach((slider, i) => slider.addEventListener("input", () => {
    const pair = anisotropyShown() || [8, 256];
    pair[i] = fromSlider(parseFloat(slider.value));
    scheduleOverride("anisotropy", pair.map(fmt).join(","));
  }));
  page.controls.push({
    update() {
      const pair = anisotropyShown();
      on.checked = !!pair;
      if (document.activeElement !== box) box.value = pair ? pair.map(fmt).join(",") : "";
      sliders.forEach((slider, i) => { slider.disabled = !pair; slider.value = toSlider(pair ? pair[i] : lo); });  // off: at the low end
    },
  });
  box.id = newId();
  const row = el("div", { class: "row number-row" }, el("label", { for: box.id, title: o.help }, on, " " + o.parameter.label), box);
  for (const slider of sliders) row.append(slider);
  return row;
}
// The [k_t, k_b] shown, or null (off).
function anisotropyShown() {
  const v = shownValue("anisotropy", undefined);
  if (v === undefined || v === null || v === "") return null;
  return (Array.isArray(v) ? v : String(v).split(",")).map(parseFloat);
}
function setAnisotropy(pair) {
  const next = cloneState(page.state);
  if (pair) {
    next.overrides.set("anisotropy", pair.map(fmt).join(","));
    next.overrides.set("reflection", "blinn-phong");
  } else next.overrides.delete("anisotropy");
  applyState(next);
}

// An "R,G,B" option (--color, --specular-color, --ambient, --background): a colour picker whose
// value is the scene's until it is changed. The picker's 8 bits a channel are written as 0..1.
function colourControl(o) {
  const name = o.name.slice(2);
  const c = el("input", { type: "color", name });
  c.addEventListener("input", () => scheduleOverride(name, rgbOf(c.value).map((x) => fmt(+x.toFixed(3))).join(",")));
  page.controls.push({
    update() {
      let v = shownValue(name, undefined);
      if (typeof v === "string") v = v.split(",").map(parseFloat);
      if (Array.isArray(v)) c.value = hex(v);
    },
  });
  return labelled(o.parameter.label, c, o.help);
}
