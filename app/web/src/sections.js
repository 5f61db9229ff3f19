// The panel: the sections of kPanelSections (core/scene/panel_sections.hpp), in its order, with the
// option controls (controls.js), the mesh and lights sections, the plots and the shader source;
// refreshPanel() shows the state drawn in all of them.
import { page, followAddress, sceneValue } from "./state.js";
import { callJson, ccall, setOverride, showError, note, titleText } from "./program.js";
import { el, labelled, fmt, fmtList, hex, rgbOf, namesOf, optionControl, switchControl } from "./controls.js";
import { camera } from "./view.js";
import { keysTable } from "./keys.js";
import { openFiles } from "./media.js";

const $ = (selector) => document.querySelector(selector);

// The options whose controls sit in a section, in the option table's order: the table says where
// (each row's section, or its parameter's: sl_describe().options[i].section).
export function sectionOptions(section) {
  return page.D.options.filter((o) => o.section === section).map((o) => o.name.slice(2));
}
// The page's own choice: a laptop's panel has room for these two open (the desktop opens more).
export const OPEN_BY_DEFAULT = new Set(["shading", "material"]);

export function buildPanel() {
  $("#panel").textContent = "";
  buildSections();
  page.sectionBodies.plots.prepend(plotsPart());
  page.sectionBodies.shader.append(...shaderPart());
  page.sectionBodies.mesh.append(meshSection());
  page.sectionBodies.lights.append(lightsSection());
  overlaysPart(page.sectionBodies.overlays);
  page.sectionBodies.camera.prepend(...cameraPart());
  page.sectionBodies.file.append(...filePart());
  // Keys: the key table.
  page.sectionBodies.keys.append(keysTable());
  const zoom = el("p", { class: "hint", text: "Ctrl+= Ctrl+- Ctrl+0 are the browser's zoom here: the page scales with it." });
  page.sectionBodies.keys.append(zoom);
}
// The <details> of each section with its options' controls.
function buildSections() {
  const panel = $("#panel");
  const state = page.state;
  let opened = null;
  if (state.overrides.has("panel-sections")) opened = new Set(String(state.overrides.get("panel-sections")).split(","));
  for (const name of page.D.sections) {
    const details = el("details", { "data-section": name, id: "section-" + name });
    details.open = opened ? opened.has(name) : OPEN_BY_DEFAULT.has(name);
    details.append(el("summary", { text: name }));
    const body = el("div", { class: "body" });
    details.append(body);
    page.sectionBodies[name] = body;
    for (const option of sectionOptions(name)) {
      const row = optionControl(option);
      if (row) body.append(row);
    }
    details.addEventListener("toggle", () => {
      if (name === "plots" && details.open) drawPlots();
      if (name === "shader" && details.open) showShader();
      sectionsToggled();
    });
    panel.append(details);
  }
}
function plotsPart() {
  const plots = el("div", { class: "plots" });
  for (const kind of page.D.plots) {
    const c = el("canvas", { "data-plot": kind, "aria-label": kind + " plot (click: larger)", role: "img", title: "click: larger / smaller" });
    c.addEventListener("click", () => {
      const big = !c.classList.contains("big");
      for (const other of document.querySelectorAll("canvas[data-plot].big")) other.classList.remove("big");
      c.classList.toggle("big", big);
      drawPlots();
    });
    plots.append(el("figure", {}, c, el("figcaption", { text: kind })));
  }
  return plots;
}
function shaderPart() {
  const shaderFile = el("select", { id: "shader-file" });
  const source = el("pre", { id: "shader-source", class: "glsl" });
  shaderFile.addEventListener("change", showShader);
  return [labelled("file", shaderFile), el("p", { class: "hint", text: "The GLSL built into the page, as it compiles it (the files in shaders/)." }), source];
}
// Overlays: one checkbox per overlay name, and --no-labels.
function overlaysPart(body) {
  const ov = page.optionByName.get("overlays");
  const group = el("fieldset", { class: "overlays" }, el("legend", { text: "overlays" }));
  for (const o of page.D.overlays) {
    const box = el("input", { type: "checkbox", name: "overlays", value: o.name });
    box.addEventListener("change", () => toggleOverlay(o.name, box.checked));
    group.append(el("label", { title: ov ? ov.help : "" }, box, " " + o.label));
    page.controls.push({ update() { box.checked = overlaysOn().includes(o.name); } });
  }
  body.append(group);
  const labels = page.optionByName.get("no-labels");
  if (labels) body.append(switchControl(labels, () => page.state.overrides.has("no-labels"), (on) => setOverride("no-labels", on ? true : null)));
}
function cameraPart() {
  const frame = el("button", { type: "button", text: "frame the model (F)" });
  frame.addEventListener("click", () => camera("frame"));
  const reset = el("button", { type: "button", text: "reset the camera (R)" });
  reset.addEventListener("click", () => camera("reset"));
  return [el("div", { class: "buttons" }, frame, reset),
    el("p", { class: "hint", text: "Left drag orbits, right or middle drag pans, the wheel zooms, a click probes." })];
}
function filePart() {
  const file = el("input", { type: "file", name: "file", multiple: true, accept: ".gltf,.glb,.json,.bin,.png,.jpg,.jpeg,.ktx2,.webp" });
  file.addEventListener("change", () => { openFiles([...file.files]); file.value = ""; });
  const fileRow = labelled("open a scene or model", file, "a .json scene, or a .gltf / .glb model; a .gltf's .bin and images chosen with it");
  fileRow.classList.add("stack");
  return [fileRow, el("p", { class: "hint", text: "Or drop the files on the page. A .gltf needs its .bin and images chosen or dropped together with it." })];
}
function sectionsToggled() {
  const state = page.state;
  const open = [...document.querySelectorAll("#panel details")].filter((d) => d.open).map((d) => d.dataset.section);
  const isDefault = open.length === OPEN_BY_DEFAULT.size && open.every((s) => OPEN_BY_DEFAULT.has(s));
  if (isDefault) state.overrides.delete("panel-sections");
  else if (open.length) state.overrides.set("panel-sections", open.join(","));
  else state.overrides.delete("panel-sections");  // "none open" has no spelling: the defaults come back on load
  followAddress();
}
export function overlaysOn() {
  const v = page.state.overrides.get("overlays");
  return v ? String(v).split(",").filter((x) => x) : [];
}
export function toggleOverlay(name, on) {
  const list = overlaysOn().filter((x) => x !== name);
  if (on) list.push(name);
  const order = page.D.overlays.map((o) => o.name);
  list.sort((a, b) => order.indexOf(a) - order.indexOf(b));
  setOverride("overlays", list.length ? list.join(",") : null);
}

// ---------------------------------------------------------------------------------------------
// --mesh: the procedural meshes with their tessellation (the parameter table's mesh rows). The
// program writes a mesh given as the scene's JSON as its --mesh shorthand (sl_mesh_option).
export function meshSpecOf(m) {
  if (!m) return "";
  const r = callJson("sl_mesh_option", ["string"], [JSON.stringify(m)]);
  return r.error ? "" : r.option;
}
export function meshSection() {
  const o = page.optionByName.get("mesh"), D = page.D;
  const text = el("input", { type: "text", name: "mesh", class: "text", spellcheck: "false" });
  const type = el("select", {});
  for (const m of D.meshes) type.append(el("option", { value: m.name, text: m.name }));
  const params = el("div", { class: "params" });
  text.addEventListener("change", () => setOverride("mesh", text.value.trim() || null));
  const compose = () => {
    const mesh = { type: type.value };
    for (const i of params.querySelectorAll("input")) mesh[i.dataset.name] = Number(i.value);
    const r = callJson("sl_mesh_option", ["string"], [JSON.stringify(mesh)]);
    if (r.error) return showError(r.error);
    setOverride("mesh", r.option);
  };
  type.addEventListener("change", () => {
    meshParams(params, D.meshes.find((m) => m.name === type.value), null, compose);
    compose();
  });
  page.controls.push({ update: () => showMesh(o, text, type, params, compose) });
  return el("div", {}, labelled("mesh", text, o.help), labelled("type", type, "the first object's mesh"), params);
}
// One number box per parameter of the mesh type (the scene's value, else the parameter's default).
function meshParams(params, mesh, scene, compose) {
  params.textContent = "";
  for (const p of mesh.parameters) {
    const current = scene && scene[p.name] !== undefined ? scene[p.name] : p.default;
    const box = el("input", { type: "number", min: p.range[0], max: p.range[1], step: 1, value: current, class: "number", "data-name": p.name });
    box.addEventListener("change", compose);
    params.append(labelled(p.label, box, p.help + " (" + p.range[0] + ".." + p.range[1] + ")"));
  }
}
function showMesh(o, text, type, params, compose) {
  const D = page.D;
  const m = page.result && sceneValue(page.result.scene, o.sets);
  if (document.activeElement !== text) text.value = page.state.overrides.get("mesh") || meshSpecOf(m);
  if (!m) return;
  const known = D.meshes.some((x) => x.name === m.type);
  if (!known && ![...type.options].some((x) => x.value === m.type)) type.append(el("option", { value: m.type, text: m.type + " (model)", disabled: true }));
  type.value = m.type;
  if (params.contains(document.activeElement)) return;
  if (known) meshParams(params, D.meshes.find((x) => x.name === m.type), m, compose);
  else params.textContent = "";
}

// ---------------------------------------------------------------------------------------------
// --light: one group per light (kind, position or direction, colour, intensity, attenuation);
// a change replaces every light with the groups' shorthands, as repeated --light options. The
// program writes a light given as the scene's JSON as its --light shorthand (sl_light_option); a
// light it refuses (a value out of range) is said in the message line and left out.
export function lightSpec(l) {
  const r = callJson("sl_light_option", ["string"], [JSON.stringify(l)]);
  if (r.error) showError(r.error);
  return r.error ? "" : r.option;
}
const sceneLights = () => (page.result && page.result.scene.lights) || [];
const lightSpecs = () => sceneLights().map(lightSpec);
const replaceLights = (specs) => setOverride("light", specs);
export function lightsSection() {
  const o = page.optionByName.get("light");
  const list = el("div");
  const add = el("button", { type: "button", text: "add a light" });
  const max = o.range ? o.range[1] : 16;
  add.addEventListener("click", () => {
    const specs = lightSpecs();
    if (specs.length >= max) return note("at most " + max + " lights", 4);
    replaceLights(specs.concat([lightSpec({ type: "point", position: [-3, 4, 3] })]));
  });
  const build = () => {
    list.textContent = "";
    sceneLights().forEach((l, i) => list.append(lightGroup(o, l, i)));
  };
  page.controls.push({ update() { if (!list.contains(document.activeElement)) build(); } });
  return el("div", {}, list, add);
}
// Light i's group: its parts, its --light shorthand and a remove button.
function lightGroup(o, l, i) {
  const group = el("fieldset", { class: "light", "data-light": i });
  group.append(el("legend", { text: "light " + i }));
  const change = (mutate) => {
    const copy = JSON.parse(JSON.stringify(sceneLights()));
    mutate(copy[i]);
    const all = lightSpecs();
    all[i] = lightSpec(copy[i]);
    if (all[i]) replaceLights(all);
  };
  group.append(...lightParts(l, change));
  const spec = el("input", { type: "text", name: "light", class: "text mono", value: lightSpec(l), spellcheck: "false" });
  spec.addEventListener("change", () => { const all = lightSpecs(); all[i] = spec.value.trim(); replaceLights(all.filter((x) => x)); });
  group.append(labelled("--light", spec, o.help));
  const remove = el("button", { type: "button", text: "remove light " + i });
  remove.addEventListener("click", () => { const all = lightSpecs(); all.splice(i, 1); replaceLights(all); });
  group.append(remove);
  return group;
}
// The rows of a light's kind, place, colour, intensity and attenuation; change(mutate) applies.
function lightParts(l, change) {
  const D = page.D;
  const kind = el("select", { "data-part": "type" });
  for (const t of D.lights.types) kind.append(el("option", { value: t, text: t }));
  kind.value = l.type;
  kind.addEventListener("change", () => change((x) => changeKind(x, kind.value)));
  const place = l.type === "directional" ? "direction" : "position";
  const at = el("input", { type: "text", class: "text", value: fmtList(l[place]), "data-part": place, spellcheck: "false" });
  at.addEventListener("change", () => change((x) => { x[place] = at.value.split(",").map(Number); }));
  const color = el("input", { type: "color", value: hex(l.color || [1, 1, 1]), "data-part": "color" });
  color.addEventListener("change", () => change((x) => { x.color = rgbOf(color.value).map((c) => +c.toFixed(3)); }));
  const intensity = el("input", { type: "number", min: D.lights.intensity[0], step: "any", value: fmt(l.intensity), class: "number", "data-part": "intensity" });
  intensity.addEventListener("change", () => change((x) => { x.intensity = Number(intensity.value); }));
  const rows = [labelled("kind", kind), labelled(place + " x,y,z", at), labelled("colour", color), labelled("intensity", intensity)];
  if (l.type !== "directional") {
    const att = el("select", { "data-part": "attenuation" });
    for (const a of D.lights.attenuation) att.append(el("option", { value: a, text: a }));
    att.value = l.attenuation || "none";
    att.addEventListener("change", () => change((x) => { x.attenuation = att.value; if (att.value === "none") delete x.range; }));
    rows.push(labelled("attenuation", att));
  }
  return rows;
}
// A light made another kind keeps its colour, intensity and falloff; a directional one points where
// the light was, and back. What only the old kind has (a spot's cones, an area's size) is dropped.
function changeKind(x, type) {
  const from = x.type;
  const keep = { type, color: x.color, intensity: x.intensity };
  if (type === "directional") keep.direction = x.direction || (x.position || [3, 4, 5]).map((c) => -c);
  else keep.position = from === "directional" ? x.direction.map((c) => -c) : x.position;
  if (type === "spot" && x.direction) keep.direction = x.direction;
  if (type !== "directional" && from !== "directional") Object.assign(keep, { attenuation: x.attenuation, range: x.range });
  for (const k of Object.keys(x)) delete x[k];
  for (const [k, v] of Object.entries(keep)) if (v !== undefined) x[k] = v;
}

// ---------------------------------------------------------------------------------------------
// The state drawn, shown in every control, the playlist's bar, the title and the caption.
export function refreshPanel() {
  const { result, state, D } = page;
  if (!result) return;
  refreshShowChoices();
  for (const c of page.controls) c.update();
  // The playlist.
  const preset = $("#preset");
  preset.value = state.preset ? String(state.preset) : state.file ? "file" : "0";
  const fileOption = preset.querySelector('option[value="file"]');
  fileOption.hidden = !state.file;
  fileOption.textContent = state.file ? "file: " + state.file : "file";
  $("#previous").disabled = state.preset <= 1 && state.preset !== 0 || !D.presets.length;
  $("#next").disabled = state.preset >= D.presets.length;
  $("#title").textContent = titleText();
  $("#caption").textContent = result.caption || "";
  if (page.hook.ready) document.title = "shadelab \u2014 " + titleText();
  const shader = $("#section-shader");
  if (shader && shader.open) showShader();
  else fillShaderFiles();
}
// --show: light:N for each light of the scene.
function refreshShowChoices() {
  const showControl = page.optionByName.get("show");
  if (!showControl) return;
  const lights = (page.result.scene.lights || []).length;
  const names = [];
  for (const n of namesOf(showControl)) {
    if (n === "light:N") for (let i = 0; i < lights; i++) names.push("light:" + i);
    else names.push(n);
  }
  const select = document.querySelector('#panel select[name="show"]');
  if (!select) return;
  const key = names.join("|");
  if (select.dataset.names === key) return;
  select.textContent = "";
  for (const n of names) select.append(el("option", { value: n, text: n }));
  select.dataset.names = key;
}

// ---------------------------------------------------------------------------------------------
// The shader section: the GLSL of the shown mode (built into the program: sl_shader).
function fillShaderFiles() {
  const select = $("#shader-file");
  if (!select || !page.result) return;
  const modes = [...new Set(page.result.panes.filter((p) => !p.difference).map((p) => p.mode))];
  const files = [];
  for (const m of modes) files.push(m + ".frag", m + ".vert");
  files.push("lighting.glsl", "lecture.glsl");
  const key = files.join("|");
  if (select.dataset.files === key) return;
  const keep = select.value;
  select.textContent = "";
  for (const f of files) select.append(el("option", { value: f, text: f }));
  select.dataset.files = key;
  const probe = page.hook.probe;
  if (files.includes(keep)) select.value = keep;
  else if (page.probeAt && probe && files.includes(probe.mode + ".frag")) select.value = probe.mode + ".frag";
}
export function showShader() {
  fillShaderFiles();
  const select = $("#shader-file"), pre = $("#shader-source");
  if (!select.value) return;
  if (pre.dataset.file === select.value) return;
  const r = callJson("sl_shader", ["string"], [select.value]);
  pre.textContent = r.error ? r.error : r.source;
  pre.dataset.file = select.value;
}

// Plots: sl_plot() draws the lecture's figure for the scene on the CPU; shown in a <canvas>.
export function drawPlots() {
  const section = $("#section-plots");
  if (!section || !section.open || !page.result) return;
  for (const c of document.querySelectorAll("canvas[data-plot]")) {
    // The figure's lettering has a fixed pixel size: the panel's plot is drawn at its smallest
    // size (320x240) to be read there; a click shows it large (800x600) over the page.
    const w = c.classList.contains("big") ? 800 : 320, h = w * 3 / 4;
    const r = callJson("sl_plot", ["string", "number", "number"], [c.dataset.plot, w, h]);
    if (r.error) {
      showError(r.error);
      continue;
    }
    const at = ccall("sl_image_data", "number");
    const bytes = new Uint8ClampedArray(page.program.HEAPU8.buffer, at, r.width * r.height * 4).slice();
    c.width = r.width;
    c.height = r.height;
    c.getContext("2d").putImageData(new ImageData(bytes, r.width, r.height), 0, 0);
  }
}
