"use strict";
// The page around the program (web_app.cpp): the panel, the keys, the camera's mouse, the playlist,
// files, plots, the probe, screenshots and recordings. Everything the panel offers comes from
// sl_describe() (the option table, the key table, the sections, the overlays, the presets), and the
// state is a command line: the panel's changed values are the options given after the input, the
// link's query parameters are the same options by their names (?preset=6&layout=compare&ke=128), and
// sl_apply() reads them with the parser of the `shadelab` program. Plain JavaScript, no libraries, no
// build step, nothing fetched: the page also works offline and from file://.

// A line where the page cannot start (the program missing, no WebGL2): never a blank page.
function shadelabFailed(text) {
  const m = document.getElementById("message");
  m.textContent = "shadelab cannot start: " + text;
  m.hidden = false;
  const n = document.getElementById("note");
  if (n) n.hidden = true;
  document.body.classList.add("failed");
  if (window.shadelab) window.shadelab.lastError = m.textContent;
}

var Module = (function () {
  const $ = (selector) => document.querySelector(selector);
  const canvas = $("#canvas");
  const LECTURE = "/share/shadelab/scenes/lecture/";
  const USER = "/user";

  // ---------------------------------------------------------------------------------------------
  // The program's functions.
  function call(name, types, args) {
    return Module.ccall(name, "string", types || [], args || []);
  }
  function callJson(name, types, args) {
    return JSON.parse(call(name, types, args));
  }

  let D = null;          // sl_describe()
  let result = null;     // the last successful sl_apply(): {scene, title, caption, panes, ...}
  let optionByName = new Map();  // "ke" -> the option table's row
  // The state: the input (null: the built-in scene), the preset it is (1-based, 0: none), the
  // options given after it. overrides: name -> true (a switch), a string, or a list (light).
  let state = { input: null, preset: 0, file: "", overrides: new Map() };
  let probeAt = null;    // [x, y] canvas pixels of the probe shown
  let recorder = null;
  const controls = [];   // {update(scene)} of every panel control
  const warnings = [];   // the program's "shadelab: warning: ..." lines since the last sl_apply()

  // ---------------------------------------------------------------------------------------------
  // Messages: #message (role=alert) holds an error in one line; #note a passing remark.
  function showError(text) {
    const m = $("#message");
    m.textContent = text;
    m.hidden = !text;
    hook.lastError = text || "";
  }
  let noteTimer = 0;
  function note(text, seconds) {
    const n = $("#note");
    n.textContent = text;
    n.hidden = !text;
    clearTimeout(noteTimer);
    if (text && seconds) noteTimer = setTimeout(() => { n.hidden = true; }, seconds * 1000);
  }

  // ---------------------------------------------------------------------------------------------
  // State <-> command line <-> link.
  const VIEW_ONLY = new Set(["size"]);  // kept when the preset changes, like the options that set no scene field
  function optionOrder(name) {
    const o = optionByName.get(name);
    return o ? D.options.indexOf(o) : 1e9;
  }
  function argsOf(s) {
    const args = s.input ? [s.input] : [];
    const names = [...s.overrides.keys()].sort((a, b) => optionOrder(a) - optionOrder(b));
    for (const name of names) {
      const v = s.overrides.get(name);
      if (v === true) args.push("--" + name);
      else if (Array.isArray(v)) for (const item of v) args.push("--" + name, item);
      else args.push("--" + name, String(v));
    }
    return args;
  }
  function encode(v) {
    return encodeURIComponent(v).replace(/%2C/gi, ",").replace(/%3A/gi, ":").replace(/%2F/gi, "/").replace(/%3D/gi, "=");
  }
  function queryOf(s) {
    const parts = [];
    if (s.preset) parts.push("preset=" + s.preset);
    const names = [...s.overrides.keys()].sort((a, b) => optionOrder(a) - optionOrder(b));
    for (const name of names) {
      const v = s.overrides.get(name);
      if (v === true) parts.push(encode(name));
      else if (Array.isArray(v)) for (const item of v) parts.push(encode(name) + "=" + encode(item));
      else parts.push(encode(name) + "=" + encode(v));
    }
    return parts.length ? "?" + parts.join("&") : "";
  }
  function followAddress() {
    const url = location.pathname + queryOf(state) + location.hash;
    try {
      history.replaceState(null, "", url);
    } catch (e) {
      // file:// in some browsers refuses replaceState: the panel still works.
    }
  }
  // The link's parameters as a state; errors name the parameter.
  function stateFromQuery(search) {
    const s = { input: null, preset: 0, file: "", overrides: new Map() };
    const problems = [];
    for (const [key, value] of new URLSearchParams(search)) {
      if (key === "preset") {
        const n = parseInt(value, 10);
        if (n >= 1 && n <= D.presets.length) {
          s.preset = n;
          s.input = D.presets[n - 1].path;
        } else problems.push("preset=" + value + ": there are presets 1.." + D.presets.length);
        continue;
      }
      const o = optionByName.get(key);
      if (!o) {
        problems.push("\"" + key + "\" is no option of shadelab");
        continue;
      }
      if (!o.argument) s.overrides.set(key, true);
      else if (key === "light") s.overrides.set(key, (s.overrides.get(key) || []).concat([value]));
      else s.overrides.set(key, value);
    }
    return { state: s, problems };
  }
  function cloneState(s) {
    const o = new Map();
    for (const [k, v] of s.overrides) o.set(k, Array.isArray(v) ? v.slice() : v);
    return { input: s.input, preset: s.preset, file: s.file, overrides: o };
  }

  // Applies a state: on success it is the page's, else the message says why and nothing changes.
  function applyState(next) {
    const r = callJson("sl_apply", ["string"], [JSON.stringify(argsOf(next))]);
    if (r.error) {
      showError(r.error);
      if (result) refreshPanel();  // the controls show the state still drawn
      return r;
    }
    state = next;
    result = r;
    showError("");
    const said = (r.warnings || []).concat(warnings.splice(0));
    if (said.length) note("warning: " + said.join("; "), 10);
    afterApply();
    return r;
  }
  function setOverride(name, value) {
    const next = cloneState(state);
    if (value === null || value === undefined) next.overrides.delete(name);
    else next.overrides.set(name, value);
    if (name === "shadows") next.overrides.delete("no-shadows");
    if (name === "no-shadows") next.overrides.delete("shadows");
    return applyState(next);
  }
  function choosePreset(n) {
    if (!D.presets.length) return;
    n = Math.max(1, Math.min(D.presets.length, n));
    const next = cloneState(state);
    for (const name of [...next.overrides.keys()]) {
      const o = optionByName.get(name);
      if (o && o.sets && !VIEW_ONLY.has(name)) next.overrides.delete(name);
    }
    next.preset = n;
    next.input = D.presets[n - 1].path;
    next.file = "";
    clearProbe();
    applyState(next);
  }

  function afterApply() {
    if (probeAt) {
      const p = callJson("sl_probe", ["number", "number"], probeAt);
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
  let framePending = false;
  function requestFrame() {
    if (framePending) return;
    framePending = true;
    requestAnimationFrame(() => {
      framePending = false;
      drawFrame();
    });
  }
  function drawFrame() {
    const r = callJson("sl_render");
    if (r.error) showError(r.error);
    hook.frames++;
    if (!hook.ready) {
      hook.ready = true;
      document.title = "shadelab \u2014 " + titleText();
    }
    if (recorder) requestFrame();  // the recording wants frames coming
  }

  // ---------------------------------------------------------------------------------------------
  // The canvas: its CSS size x devicePixelRatio is its pixel size unless --size pins it.
  function layoutCanvas() {
    const view = $("#view");
    const box = view.getBoundingClientRect();
    const dpr = window.devicePixelRatio || 1;
    if (result && result.pinned) {
      // The pinned picture at one canvas pixel per CSS pixel (as the browser shows an image at
      // 100%), smaller where the view is.
      const scale = Math.min(1, box.width / result.width, box.height / result.height);
      canvas.style.width = (result.width * scale) + "px";
      canvas.style.height = (result.height * scale) + "px";
    } else {
      canvas.style.width = "100%";
      canvas.style.height = "100%";
      const w = Math.max(16, Math.round(box.width * dpr)), h = Math.max(16, Math.round(box.height * dpr));
      if (Module.calledRun && (w !== canvas.width || h !== canvas.height)) {
        const r = callJson("sl_resize", ["number", "number"], [w, h]);
        if (r.panes && result) Object.assign(result, { panes: r.panes, width: r.width, height: r.height });
        if (probeAt) clearProbe();
        // A resized canvas is blank: drawn at once, before the browser shows it.
        if (hook.ready) drawFrame();
      }
    }
    drawLabels();
    requestFrame();
  }
  // Canvas pixels per CSS pixel.
  function canvasScale() {
    const rect = canvas.getBoundingClientRect();
    return rect.width > 0 ? canvas.width / rect.width : 1;
  }

  // Pane labels (flat / Gouraud / Phong, the difference) over each pane.
  const MODE_LABEL = { flat: "flat", gouraud: "Gouraud", phong: "Phong" };
  function drawLabels() {
    const box = $("#labels");
    box.textContent = "";
    if (!result || state.overrides.has("no-labels")) return;
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

  function titleText() {
    if (!result) return "";
    if (result.title) return result.title;
    if (state.file) return state.file;
    if (state.preset) return D.presets[state.preset - 1].name;
    return "the built-in scene";
  }

  // ---------------------------------------------------------------------------------------------
  // Formatting.
  function fmt(x) {
    if (typeof x !== "number") return String(x);
    if (!isFinite(x)) return String(x);
    const r = Math.abs(x) >= 1e-3 || x === 0 ? +x.toPrecision(5) : +x.toPrecision(3);
    return String(r);
  }
  function fmtList(a) { return a.map(fmt).join(","); }
  function el(tag, attributes, ...children) {
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
  let uid = 0;
  function labelled(text, input, help) {
    if (!input.id) input.id = "c" + (++uid);
    const row = el("div", { class: "row" }, el("label", { for: input.id, text: text, title: help || undefined }), input);
    return row;
  }
  function hex(rgb) {
    return "#" + rgb.map((c) => Math.round(Math.max(0, Math.min(1, c)) * 255).toString(16).padStart(2, "0")).join("");
  }
  function rgbOf(hexText) {
    return [1, 3, 5].map((i) => parseInt(hexText.substr(i, 2), 16) / 255);
  }

  // The scene's value at an option's `sets` path: "objects[].material.ke" is the first object's
  // (a scene of one object writes it at the top: "material.ke"); "diff.a, diff.b" joins both.
  function sceneValue(scene, sets) {
    const get = (path) => {
      let cur = scene;
      for (const part of path.replace(/\[\]/g, ".0").replace(/\[(\d+)\]/g, ".$1").split(".")) {
        if (cur === null || cur === undefined) return undefined;
        cur = cur[part];
      }
      return cur;
    };
    const one = (path) => {
      let v = get(path);
      if (v === undefined && path.startsWith("objects")) v = get(path.replace(/^objects(\[\d*\])?\./, ""));
      return v;
    };
    const paths = sets.split(",").map((p) => p.trim());
    return paths.length > 1 ? paths.map(one).join(",") : one(paths[0]);
  }
  // What an option's control shows: the override, else the scene's value, else the default.
  function shownValue(name, fallback) {
    if (state.overrides.has(name)) return state.overrides.get(name);
    const o = optionByName.get(name);
    const v = o && o.sets && result ? sceneValue(result.scene, o.sets) : undefined;
    return v === undefined ? fallback : v;
  }
  function namesOf(o) {
    return (o.names || "").split(/\s*(?:\||,|\bor\b)\s*/).filter((n) => n);
  }
  function defaultFromHelp(o) {
    const m = /default ([-\w.]+)/.exec(o.help || "");
    return m ? m[1] : "";
  }

  // ---------------------------------------------------------------------------------------------
  // The panel's controls, generated from the option table.
  function choiceControl(o, names, fallback) {
    const name = o.name.slice(2);
    const select = el("select", { name });
    for (const n of names) select.append(el("option", { value: n, text: n }));
    select.addEventListener("change", () => setOverride(name, select.value));
    controls.push({
      update() {
        const v = String(shownValue(name, fallback));
        if (![...select.options].some((x) => x.value === v)) select.append(el("option", { value: v, text: v }));
        select.value = v;
      },
    });
    return labelled(name, select, o.help);
  }
  // A number of the table's range: a slider (logarithmic over a range of a hundredfold or more, as
  // k_e's) and a number box. `sliderRange` narrows the slider where the table's is too wide to aim
  // in (k_a, k_d, k_s: the desktop panel's 0..1); the number box takes the whole range.
  function numberControl(o, fallback, sliderRange) {
    const name = o.name.slice(2);
    const [lo, hi] = o.range;
    const [slo, shi] = sliderRange || [lo, hi];
    const log = slo > 0 && shi / slo >= 100;
    const integer = /^(N|DEG)$/.test(o.argument) && name !== "incidence";
    const toSlider = (v) => (log ? Math.log10(Math.max(slo, v)) : v);
    const fromSlider = (t) => (log ? Math.pow(10, t) : t);
    const slider = el("input", {
      type: "range", "aria-label": name + (log ? " (logarithmic slider)" : " (slider)"),
      min: toSlider(slo), max: toSlider(shi), step: log ? (Math.log10(shi) - Math.log10(slo)) / 1000 : (shi - slo) / 1000,
    });
    const box = el("input", { type: "number", name, min: lo, max: hi, step: "any", class: "number" });
    slider.addEventListener("input", () => {
      let v = fromSlider(parseFloat(slider.value));
      v = log ? +v.toPrecision(3) : +v.toFixed(integer ? 0 : 3);
      box.value = fmt(v);
      scheduleOverride(name, fmt(v));
    });
    box.addEventListener("change", () => setOverride(name, box.value === "" ? null : box.value.trim()));
    const control = {
      update() {
        const v = shownValue(name, fallback);
        // Unset (a material's mirror or transmission): an empty box and the slider at its
        // low end, dimmed, until a value is given.
        const unset = v === undefined || v === "";
        slider.classList.toggle("unset", unset);
        if (unset) {
          box.value = "";
          slider.value = toSlider(slo);
          return;
        }
        const x = parseFloat(v);
        if (document.activeElement !== box) box.value = fmt(x);
        slider.value = toSlider(x);
      },
    };
    controls.push(control);
    const row = labelled(name, box, o.help);
    row.classList.add("number-row");
    row.append(slider);
    return row;
  }
  function switchControl(o, checkedOf, onChange) {
    const name = o.name.slice(2);
    const box = el("input", { type: "checkbox", name });
    box.addEventListener("change", () => onChange(box.checked));
    controls.push({ update() { box.checked = !!checkedOf(); } });
    const row = el("div", { class: "row check" }, el("label", { title: o.help }, box, " " + name));
    return row;
  }
  function simpleSwitch(o) {
    const name = o.name.slice(2);
    return switchControl(o, () => state.overrides.get(name) === true, (on) => setOverride(name, on ? true : null));
  }
  // Slider changes are applied once a frame, however fast the input events come.
  // One that comes after the input changed (another preset, a file) is dropped.
  let pendingOverride = null;
  function scheduleOverride(name, value) {
    const first = !pendingOverride;
    pendingOverride = [name, value, state.input];
    if (first) requestAnimationFrame(() => {
      const [n, v, input] = pendingOverride;
      pendingOverride = null;
      if (input === state.input) setOverride(n, v);
    });
  }

  function optionControl(name) {
    const o = optionByName.get(name);
    if (!o) return null;
    switch (name) {
      case "diff": {
        const modes = namesOf(o), pairs = [];
        for (const a of modes) for (const b of modes) if (a !== b) pairs.push(a + "," + b);
        return choiceControl(o, pairs);
      }
      case "show": return choiceControl(o, namesOf(o));  // light:N filled per scene in refreshPanel
      case "msaa": return choiceControl(o, namesOf(o), "4");  // web_app.cpp draws with 4 unless --msaa
      case "ka": case "kd": case "ks": return numberControl(o, undefined, [0, 1]);
      case "anisotropy": return anisotropyControl(o);
      case "color": return colourControl(o, "C colour");
      case "specular-color": return colourControl(o, "S colour");
      case "ambient": return colourControl(o, "A ambient");
      case "background": return colourControl(o, "background");
      case "incidence": return numberControl(o, defaultFromHelp(o));
      case "shadows":
        return switchControl(o, () => result.scene.shadows === true, (on) => setOverride(on ? "shadows" : "no-shadows", true));
      case "size": {
        const box = el("input", { type: "text", name, placeholder: "follows the window", pattern: "\\d+x\\d+", class: "text", spellcheck: "false" });
        box.addEventListener("change", () => setOverride(name, box.value.trim() || null));
        controls.push({ update() { if (document.activeElement !== box) box.value = state.overrides.get(name) || ""; } });
        return labelled(name + " (pins WxH)", box, o.help);
      }
    }
    if (o.names && o.argument) return choiceControl(o, namesOf(o), defaultFromHelp(o));
    if (o.range && o.argument) return numberControl(o, defaultFromHelp(o));
    if (!o.argument) return simpleSwitch(o);
    return null;
  }

  // --mesh: the procedural meshes with their tessellation, composed into the shorthand.
  function meshSpecOf(m) {
    if (!m) return "";
    switch (m.type) {
      case "uvsphere": return "uvsphere:" + m.slices + ":" + m.stacks;
      case "icosphere": return "icosphere:" + m.subdivisions;
      case "torus": return "torus:" + m.major_segments + ":" + m.minor_segments;
      case "plane": return "plane:" + m.subdivisions;
      case "gltf": return m.path || "";
      default: return m.type;
    }
  }
  function meshSection() {
    const o = optionByName.get("mesh");
    const part = el("div");
    const text = el("input", { type: "text", name: "mesh", class: "text", spellcheck: "false" });
    const type = el("select", {});
    for (const m of D.meshes) type.append(el("option", { value: m.name, text: m.name }));
    const params = el("div", { class: "params" });
    text.addEventListener("change", () => setOverride("mesh", text.value.trim() || null));
    const compose = () => {
      const mesh = D.meshes.find((m) => m.name === type.value);
      const values = [...params.querySelectorAll("input")].map((i) => i.value);
      setOverride("mesh", [mesh.name].concat(values).join(":"));
    };
    type.addEventListener("change", () => {
      params.textContent = "";
      buildParams(D.meshes.find((m) => m.name === type.value), null);
      compose();
    });
    const buildParams = (mesh, scene) => {
      params.textContent = "";
      for (const p of mesh.parameters) {
        const current = scene && scene[p.name] !== undefined ? scene[p.name] : Math.min(p.range[1], Math.max(p.range[0], p.name === "stacks" ? 16 : p.name === "subdivisions" ? 3 : 32));
        const box = el("input", { type: "number", min: p.range[0], max: p.range[1], step: 1, value: current, class: "number" });
        box.addEventListener("change", compose);
        params.append(labelled(p.name.replace("_", " "), box, p.name + " (" + p.range[0] + ".." + p.range[1] + ")"));
      }
    };
    controls.push({
      update() {
        const m = result && sceneValue(result.scene, o.sets);
        if (document.activeElement !== text) text.value = state.overrides.get("mesh") || meshSpecOf(m);
        if (!m) return;
        const known = D.meshes.some((x) => x.name === m.type);
        if (!known && ![...type.options].some((x) => x.value === m.type)) type.append(el("option", { value: m.type, text: m.type + " (model)", disabled: true }));
        type.value = m.type;
        if (params.contains(document.activeElement)) return;
        if (known) buildParams(D.meshes.find((x) => x.name === m.type), m);
        else params.textContent = "";
      },
    });
    part.append(labelled("mesh", text, o.help), labelled("type", type, "the first object's mesh"), params);
    return part;
  }

  // --light: one group per light (kind, position or direction, colour, intensity, attenuation);
  // a change replaces every light with the groups' shorthands, as repeated --light options.
  function lightSpec(l) {
    const v = fmtList;
    let s = l.type + ":" + v(l.type === "directional" ? l.direction : l.position);
    if (l.color) s += ":color=" + v(l.color);
    if (l.intensity !== undefined) s += ":intensity=" + fmt(l.intensity);
    if (l.type !== "directional") {
      if (l.attenuation) s += ":attenuation=" + l.attenuation;
      if (l.range) s += ":range=" + fmt(l.range);
    }
    if (l.type === "area") {
      if (l.normal) s += ":normal=" + v(l.normal);
      if (l.size) s += ":size=" + v(l.size);
      if (l.samples) s += ":samples=" + l.samples[0] + "x" + l.samples[1];
      if (l.two_sided) s += ":two-sided";
    }
    if (l.type === "spot") {
      if (l.direction) s += ":direction=" + v(l.direction);
      if (l.outer_cone_deg !== undefined) s += ":outer=" + fmt(l.outer_cone_deg);
      if (l.inner_cone_deg !== undefined) s += ":inner=" + fmt(l.inner_cone_deg);
    }
    return s;
  }
  function lightsSection() {
    const o = optionByName.get("light");
    const part = el("div");
    const list = el("div");
    const add = el("button", { type: "button", text: "add a light" });
    const max = o.range ? o.range[1] : 16;
    const lights = () => (result && result.scene.lights) || [];
    const replace = (specs) => setOverride("light", specs);
    add.addEventListener("click", () => {
      const specs = lights().map(lightSpec);
      if (specs.length >= max) return note("at most " + max + " lights", 4);
      replace(specs.concat(["point:-3,4,3"]));
    });
    const build = () => {
      list.textContent = "";
      lights().forEach((l, i) => {
        const group = el("fieldset", { class: "light", "data-light": i });
        group.append(el("legend", { text: "light " + i }));
        const specs = () => lights().map(lightSpec);
        const change = (mutate) => {
          const copy = JSON.parse(JSON.stringify(lights()));
          mutate(copy[i]);
          const all = specs();
          all[i] = lightSpec(copy[i]);
          replace(all);
        };
        const kind = el("select", { "data-part": "type" });
        for (const t of D.lights.types) kind.append(el("option", { value: t, text: t }));
        kind.value = l.type;
        kind.addEventListener("change", () => change((x) => {
          const from = x.type;
          x.type = kind.value;
          if (x.type === "directional") x.direction = x.direction || (x.position || [3, 4, 5]).map((c) => -c);
          if (from === "directional" && !x.position) x.position = x.direction.map((c) => -c);
          if (x.type !== "spot" && x.type !== "directional") delete x.direction;
        }));
        const place = l.type === "directional" ? "direction" : "position";
        const at = el("input", { type: "text", class: "text", value: fmtList(l[place]), "data-part": place, spellcheck: "false" });
        at.addEventListener("change", () => change((x) => { x[place] = at.value.split(",").map(Number); }));
        const color = el("input", { type: "color", value: hex(l.color || [1, 1, 1]), "data-part": "color" });
        color.addEventListener("change", () => change((x) => { x.color = rgbOf(color.value).map((c) => +c.toFixed(3)); }));
        const intensity = el("input", { type: "number", min: D.lights.intensity[0], step: "any", value: fmt(l.intensity), class: "number", "data-part": "intensity" });
        intensity.addEventListener("change", () => change((x) => { x.intensity = Number(intensity.value); }));
        group.append(labelled("kind", kind), labelled(place + " x,y,z", at), labelled("colour", color), labelled("intensity", intensity));
        if (l.type !== "directional") {
          const att = el("select", { "data-part": "attenuation" });
          for (const a of D.lights.attenuation) att.append(el("option", { value: a, text: a }));
          att.value = l.attenuation || "none";
          att.addEventListener("change", () => change((x) => { x.attenuation = att.value; if (att.value === "none") delete x.range; }));
          group.append(labelled("attenuation", att));
        }
        const spec = el("input", { type: "text", name: "light", class: "text mono", value: lightSpec(l), spellcheck: "false" });
        spec.addEventListener("change", () => { const all = specs(); all[i] = spec.value.trim(); replace(all.filter((x) => x)); });
        group.append(labelled("--light", spec, o.help));
        const remove = el("button", { type: "button", text: "remove light " + i });
        remove.addEventListener("click", () => { const all = specs(); all.splice(i, 1); replace(all); });
        group.append(remove);
        list.append(group);
      });
    };
    controls.push({ update() { if (!list.contains(document.activeElement)) build(); } });
    part.append(list, add);
    return part;
  }

  // --anisotropy KT,KB: a switch and two logarithmic sliders (k_t along the tangent, k_b along the
  // bitangent), as the desktop panel's. Off is no override: the scene's own (usually none). The
  // lobe is Blinn-Phong's (the option needs --reflection blinn-phong): switched on, it asks for it.
  function anisotropyControl(o) {
    const [lo, hi] = o.range;
    const toSlider = (v) => Math.log10(Math.max(lo, v)), fromSlider = (t) => +Math.pow(10, t).toPrecision(3);
    const on = el("input", { type: "checkbox", "aria-label": "anisotropy on" });
    const box = el("input", { type: "text", name: "anisotropy", class: "text", spellcheck: "false", placeholder: "KT,KB e.g. 8,256" });
    const sliders = ["k_t (tangent)", "k_b (bitangent)"].map((label) =>
      el("input", { type: "range", "aria-label": label + " (logarithmic slider)", min: toSlider(lo), max: toSlider(hi), step: (toSlider(hi) - toSlider(lo)) / 1000 }));
    const current = () => {
      const v = shownValue("anisotropy", undefined);
      if (v === undefined || v === null || v === "") return null;
      return (Array.isArray(v) ? v : String(v).split(",")).map(parseFloat);
    };
    const set = (pair) => {
      const next = cloneState(state);
      if (pair) {
        next.overrides.set("anisotropy", pair.map(fmt).join(","));
        next.overrides.set("reflection", "blinn-phong");
      } else next.overrides.delete("anisotropy");
      applyState(next);
    };
    on.addEventListener("change", () => set(on.checked ? [8, 256] : null));
    box.addEventListener("change", () => set(box.value.trim() ? box.value.trim().split(",").map(parseFloat) : null));
    sliders.forEach((slider, i) => slider.addEventListener("input", () => {
      const pair = current() || [8, 256];
      pair[i] = fromSlider(parseFloat(slider.value));
      scheduleOverride("anisotropy", pair.map(fmt).join(","));
    }));
    controls.push({
      update() {
        const pair = current();
        on.checked = !!pair;
        if (document.activeElement !== box) box.value = pair ? pair.map(fmt).join(",") : "";
        sliders.forEach((slider, i) => { slider.disabled = !pair; slider.value = toSlider(pair ? pair[i] : lo); });  // off: at the low end
      },
    });
    box.id = "c" + (++uid);
    const row = el("div", { class: "row number-row" }, el("label", { for: box.id, title: o.help }, on, " anisotropy"), box);
    for (const slider of sliders) row.append(slider);
    return row;
  }

  // An "R,G,B" option (--color, --specular-color, --ambient, --background): a colour picker whose
  // value is the scene's until it is changed. The picker's 8 bits a channel are written as 0..1.
  function colourControl(o, label) {
    const name = o.name.slice(2);
    const c = el("input", { type: "color", name });
    c.addEventListener("input", () => scheduleOverride(name, rgbOf(c.value).map((x) => fmt(+x.toFixed(3))).join(",")));
    controls.push({
      update() {
        let v = shownValue(name, undefined);
        if (typeof v === "string") v = v.split(",").map(parseFloat);
        if (Array.isArray(v)) c.value = hex(v);
      },
    });
    return labelled(label, c, o.help);
  }

  // ---------------------------------------------------------------------------------------------
  // The panel: the sections of kPanelSections (core/scene/panel_sections.hpp), in its order.
  // Which option sits in which section is the page's choice (the table has no section column).
  const SECTION_OPTIONS = {
    shading: ["layout", "shading", "diff", "diff-factor", "reflection", "specular-normalization", "fresnel", "ior", "show", "output-encoding", "msaa"],
    material: ["ka", "kd", "ks", "ke", "anisotropy", "mirror", "transmission", "color", "specular-color", "no-textures"],
    plots: ["incidence", "from-inside"],
    shadows: ["shadows"],
    overlays: ["formula"],
    camera: ["size"],
    background: ["environment", "background", "ambient"],
  };
  const OPEN_BY_DEFAULT = new Set(["shading", "material"]);
  const sectionBodies = {};
  function buildPanel() {
    const panel = $("#panel");
    panel.textContent = "";
    const sections = D.sections;
    let opened = null;
    if (state.overrides.has("panel-sections")) opened = new Set(String(state.overrides.get("panel-sections")).split(","));
    for (const name of sections) {
      const details = el("details", { "data-section": name, id: "section-" + name });
      details.open = opened ? opened.has(name) : OPEN_BY_DEFAULT.has(name);
      details.append(el("summary", { text: name }));
      const body = el("div", { class: "body" });
      details.append(body);
      sectionBodies[name] = body;
      for (const option of SECTION_OPTIONS[name] || []) {
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
    // Plots.
    const plots = el("div", { class: "plots" });
    for (const kind of D.plots) {
      const c = el("canvas", { "data-plot": kind, "aria-label": kind + " plot (click: larger)", role: "img", title: "click: larger / smaller" });
      c.addEventListener("click", () => {
        const big = !c.classList.contains("big");
        for (const other of document.querySelectorAll("canvas[data-plot].big")) other.classList.remove("big");
        c.classList.toggle("big", big);
        drawPlots();
      });
      plots.append(el("figure", {}, c, el("figcaption", { text: kind })));
    }
    sectionBodies.plots.prepend(plots);
    // Shader.
    const shaderFile = el("select", { id: "shader-file" });
    const source = el("pre", { id: "shader-source", class: "glsl" });
    shaderFile.addEventListener("change", showShader);
    sectionBodies.shader.append(labelled("file", shaderFile), el("p", { class: "hint", text: "The GLSL built into the page, as it compiles it (the files in shaders/)." }), source);
    // Mesh, lights.
    sectionBodies.mesh.append(meshSection());
    sectionBodies.lights.append(lightsSection());
    // Overlays: one checkbox per overlay name.
    const ov = optionByName.get("overlays");
    const group = el("fieldset", { class: "overlays" }, el("legend", { text: "overlays" }));
    for (const o of D.overlays) {
      const box = el("input", { type: "checkbox", name: "overlays", value: o.name });
      box.addEventListener("change", () => toggleOverlay(o.name, box.checked));
      group.append(el("label", { title: ov ? ov.help : "" }, box, " " + o.label));
      controls.push({ update() { box.checked = overlaysOn().includes(o.name); } });
    }
    sectionBodies.overlays.append(group);
    const labels = optionByName.get("no-labels");
    if (labels) sectionBodies.overlays.append(switchControl(labels, () => state.overrides.has("no-labels"), (on) => setOverride("no-labels", on ? true : null)));
    // Camera.
    const frame = el("button", { type: "button", text: "frame the model (F)" });
    frame.addEventListener("click", () => camera("frame"));
    const reset = el("button", { type: "button", text: "reset the camera (R)" });
    reset.addEventListener("click", () => camera("reset"));
    sectionBodies.camera.prepend(el("div", { class: "buttons" }, frame, reset),
      el("p", { class: "hint", text: "Left drag orbits, right or middle drag pans, the wheel zooms, a click probes." }));
    // File.
    const file = el("input", { type: "file", name: "file", multiple: true, accept: ".gltf,.glb,.json,.bin,.png,.jpg,.jpeg,.ktx2,.webp" });
    file.addEventListener("change", () => { openFiles([...file.files]); file.value = ""; });
    const fileRow = labelled("open a scene or model", file, "a .json scene, or a .gltf / .glb model; a .gltf's .bin and images chosen with it");
    fileRow.classList.add("stack");
    sectionBodies.file.append(fileRow,
      el("p", { class: "hint", text: "Or drop the files on the page. A .gltf needs its .bin and images chosen or dropped together with it." }));
    // Keys: the key table.
    sectionBodies.keys.append(keysTable());
    const zoom = el("p", { class: "hint", text: "Ctrl+= Ctrl+- Ctrl+0 are the browser's zoom here: the page scales with it." });
    sectionBodies.keys.append(zoom);
  }
  function sectionsToggled() {
    const open = [...document.querySelectorAll("#panel details")].filter((d) => d.open).map((d) => d.dataset.section);
    const isDefault = open.length === OPEN_BY_DEFAULT.size && open.every((s) => OPEN_BY_DEFAULT.has(s));
    if (isDefault) state.overrides.delete("panel-sections");
    else if (open.length) state.overrides.set("panel-sections", open.join(","));
    else state.overrides.delete("panel-sections");  // "none open" has no spelling: the defaults come back on load
    followAddress();
  }
  function overlaysOn() {
    const v = state.overrides.get("overlays");
    return v ? String(v).split(",").filter((x) => x) : [];
  }
  function toggleOverlay(name, on) {
    const list = overlaysOn().filter((x) => x !== name);
    if (on) list.push(name);
    const order = D.overlays.map((o) => o.name);
    list.sort((a, b) => order.indexOf(a) - order.indexOf(b));
    setOverride("overlays", list.length ? list.join(",") : null);
  }

  function refreshPanel() {
    if (!result) return;
    // show: light:N for each light of the scene.
    const showControl = optionByName.get("show");
    if (showControl) {
      const lights = (result.scene.lights || []).length;
      const names = [];
      for (const n of namesOf(showControl)) {
        if (n === "light:N") for (let i = 0; i < lights; i++) names.push("light:" + i);
        else names.push(n);
      }
      const select = document.querySelector('#panel select[name="show"]');
      if (select) {
        const key = names.join("|");
        if (select.dataset.names !== key) {
          select.textContent = "";
          for (const n of names) select.append(el("option", { value: n, text: n }));
          select.dataset.names = key;
        }
      }
    }
    for (const c of controls) c.update();
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
    if (hook.ready) document.title = "shadelab \u2014 " + titleText();
    const shader = $("#section-shader");
    if (shader && shader.open) showShader();
    else fillShaderFiles();
  }

  // ---------------------------------------------------------------------------------------------
  // The shader section: the GLSL of the shown mode (built into the program: sl_shader).
  function fillShaderFiles() {
    const select = $("#shader-file");
    if (!select || !result) return;
    const modes = [...new Set(result.panes.filter((p) => !p.difference).map((p) => p.mode))];
    const files = [];
    for (const m of modes) files.push(m + ".frag", m + ".vert");
    files.push("lighting.glsl", "lecture.glsl");
    const key = files.join("|");
    if (select.dataset.files === key) return;
    const keep = select.value;
    select.textContent = "";
    for (const f of files) select.append(el("option", { value: f, text: f }));
    select.dataset.files = key;
    if (files.includes(keep)) select.value = keep;
    else if (probeAt && hook.probe && files.includes(hook.probe.mode + ".frag")) select.value = hook.probe.mode + ".frag";
  }
  function showShader() {
    fillShaderFiles();
    const select = $("#shader-file"), pre = $("#shader-source");
    if (!select.value) return;
    if (pre.dataset.file === select.value) return;
    const r = callJson("sl_shader", ["string"], [select.value]);
    pre.textContent = r.error ? r.error : r.source;
    pre.dataset.file = select.value;
  }

  // ---------------------------------------------------------------------------------------------
  // Plots: sl_plot() draws the lecture's figure for the scene on the CPU; shown in a <canvas>.
  function drawPlots() {
    const section = $("#section-plots");
    if (!section || !section.open || !result) return;
    for (const c of document.querySelectorAll("canvas[data-plot]")) {
      // The figure's lettering has a fixed pixel size: the panel's plot is drawn at its smallest
      // size (320x240) to be read there; a click shows it large (800x600) over the page.
      const w = c.classList.contains("big") ? 800 : 320, h = w * 3 / 4;
      const r = callJson("sl_plot", ["string", "number", "number"], [c.dataset.plot, w, h]);
      if (r.error) {
        showError(r.error);
        continue;
      }
      const at = Module.ccall("sl_image_data", "number", [], []);
      const bytes = new Uint8ClampedArray(Module.HEAPU8.buffer, at, r.width * r.height * 4).slice();
      c.width = r.width;
      c.height = r.height;
      c.getContext("2d").putImageData(new ImageData(bytes, r.width, r.height), 0, 0);
    }
  }

  // ---------------------------------------------------------------------------------------------
  // The probe: a click without a drag; the terms in a table over the view.
  function probe(x, y) {
    const p = callJson("sl_probe", ["number", "number"], [x, y]);
    if (p.error) {
      showError(p.error);
      return p;
    }
    probeAt = [x, y];
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
  function showProbe(p) {
    hook.probe = p;
    const box = $("#probe");
    box.textContent = "";
    const head = el("div", { class: "probe-head" });
    head.append(el("strong", { text: "probe " + p.pixel.join(", ") }));
    const close = el("button", { type: "button", class: "close", text: "\u00d7", "aria-label": "clear the probe (Esc)" });
    close.addEventListener("click", clearProbe);
    head.append(close);
    box.append(head);
    const table = el("table");
    const row = (k, v, cls) => table.append(el("tr", { class: cls }, el("th", { text: k }), el("td", { text: vec(v) })));
    const section = (text) => table.append(el("tr", { class: "group" }, el("th", { colspan: 2, text })));
    if (p.miss) {
      row("miss", true);
      for (const k of ["background", "output_8bit"]) if (p[k] !== undefined) row(k, p[k]);
    } else {
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
    }
    box.append(table);
    box.hidden = false;
    // The table on the other side of the view from the probed pixel.
    box.classList.toggle("left", p.pixel[0] > canvas.width / 2);
    const mark = $("#probe-mark");
    const s = canvasScale(), rect = canvas.getBoundingClientRect(), view = $("#view").getBoundingClientRect();
    mark.style.left = (rect.left - view.left + (p.pixel[0] + 0.5) / s) + "px";
    mark.style.top = (rect.top - view.top + (p.pixel[1] + 0.5) / s) + "px";
    mark.hidden = false;
  }
  function clearProbe() {
    if (!probeAt && $("#probe").hidden) return;
    probeAt = null;
    hook.probe = null;
    if (Module.calledRun) Module.ccall("sl_clear_probe", null, [], []);
    $("#probe").hidden = true;
    $("#probe-mark").hidden = true;
    requestFrame();
  }

  // ---------------------------------------------------------------------------------------------
  // The camera: pointer drags and the wheel over the canvas.
  function camera(what) {
    Module.ccall("sl_camera", null, ["string"], [what]);
    clearProbe();
    requestFrame();
  }
  const DRAG_THRESHOLD = 4;  // CSS pixels before a press is a drag, not a click
  let drag = null;
  canvas.addEventListener("pointerdown", (e) => {
    if (!Module.calledRun) return;
    canvas.focus({ preventScroll: true });
    canvas.setPointerCapture(e.pointerId);
    drag = { id: e.pointerId, button: e.button, x: e.clientX, y: e.clientY, startX: e.clientX, startY: e.clientY, moved: false };
    e.preventDefault();
  });
  canvas.addEventListener("pointermove", (e) => {
    if (!drag || e.pointerId !== drag.id) return;
    const dx = e.clientX - drag.x, dy = e.clientY - drag.y;
    if (!drag.moved && Math.hypot(e.clientX - drag.startX, e.clientY - drag.startY) < DRAG_THRESHOLD) return;
    if (!drag.moved) clearProbe();
    drag.moved = true;
    drag.x = e.clientX;
    drag.y = e.clientY;
    if (drag.button === 0) {
      // CSS pixels: the same turn per hand movement as the desktop viewer at any device scale.
      Module.ccall("sl_orbit", null, ["number", "number"], [dx, dy]);
    } else {
      // Canvas pixels: the model follows the pointer.
      const s = canvasScale();
      Module.ccall("sl_pan", null, ["number", "number"], [dx * s, dy * s]);
    }
    requestFrame();
  });
  function endDrag(e) {
    if (!drag || e.pointerId !== drag.id) return;
    const d = drag;
    drag = null;
    if (e.type === "pointerup" && !d.moved && d.button === 0) {
      const rect = canvas.getBoundingClientRect(), s = canvasScale();
      const x = Math.floor((e.clientX - rect.left) * s), y = Math.floor((e.clientY - rect.top) * s);
      if (x >= 0 && y >= 0 && x < canvas.width && y < canvas.height) probe(x, y);
    }
  }
  canvas.addEventListener("pointerup", endDrag);
  canvas.addEventListener("pointercancel", endDrag);
  canvas.addEventListener("contextmenu", (e) => e.preventDefault());
  canvas.addEventListener("wheel", (e) => {
    if (!Module.calledRun) return;
    e.preventDefault();
    // One notch (100 pixels, or 3 lines) is one step; forward (deltaY < 0) zooms in, as the desktop wheel.
    const steps = -e.deltaY / (e.deltaMode === 1 ? 3 : e.deltaMode === 2 ? 1 : 100);
    Module.ccall("sl_zoom", null, ["number"], [steps]);
    clearProbe();
    requestFrame();
  }, { passive: false });

  // ---------------------------------------------------------------------------------------------
  // Screenshot and recording.
  function stamp() {
    const d = new Date(), p = (n) => String(n).padStart(2, "0");
    return d.getFullYear() + p(d.getMonth() + 1) + p(d.getDate()) + "-" + p(d.getHours()) + p(d.getMinutes()) + p(d.getSeconds());
  }
  function baseName() {
    const n = state.preset ? D.presets[state.preset - 1].name : state.file ? state.file.replace(/\.[^.]*$/, "") : "scene";
    return "shadelab-" + n + "-" + stamp();
  }
  function download(blob, name) {
    const a = el("a", { href: URL.createObjectURL(blob), download: name });
    document.body.append(a);
    a.click();
    a.remove();
    setTimeout(() => URL.revokeObjectURL(a.href), 10000);
  }
  function screenshot() {
    callJson("sl_render");  // the frame as it is now (the drawing buffer is preserved)
    const name = baseName() + ".png";
    canvas.toBlob((blob) => {
      if (!blob) return showError("screenshot: the browser gave no PNG of the canvas");
      download(blob, name);
      note("screenshot: " + name, 4);
    }, "image/png");
  }
  function record() {
    if (recorder) {
      recorder.stop();
      return;
    }
    if (typeof MediaRecorder === "undefined" || !canvas.captureStream) {
      showError("record: this browser cannot record a canvas (no MediaRecorder)");
      return;
    }
    const type = ["video/webm;codecs=vp9", "video/webm;codecs=vp8", "video/webm"].find((t) => MediaRecorder.isTypeSupported(t));
    if (!type) {
      showError("record: this browser cannot write WebM");
      return;
    }
    const chunks = [], name = baseName() + ".webm";
    const r = new MediaRecorder(canvas.captureStream(30), { mimeType: type });
    r.ondataavailable = (e) => { if (e.data && e.data.size) chunks.push(e.data); };
    r.onstop = () => {
      recorder = null;
      $("#record").textContent = "record";
      $("#record").classList.remove("recording");
      download(new Blob(chunks, { type: "video/webm" }), name);
      note("recorded: " + name, 4);
    };
    r.start(1000);
    recorder = r;
    $("#record").textContent = "\u25cf stop recording";
    $("#record").classList.add("recording");
    note("recording the view to WebM (Ctrl+R or the button stops)");
    requestFrame();
  }

  // ---------------------------------------------------------------------------------------------
  // Files: written into the program's file system under /user and opened as the input.
  async function openFiles(files) {
    if (!files.length) return;
    try {
      try { Module.FS.mkdir(USER); } catch (e) { /* it exists */ }
      for (const f of files) Module.FS.writeFile(USER + "/" + f.name, new Uint8Array(await f.arrayBuffer()));
    } catch (e) {
      showError("could not read the file: " + (e && e.message ? e.message : e));
      return;
    }
    const main = files.find((f) => /\.json$/i.test(f.name)) || files.find((f) => /\.(gltf|glb)$/i.test(f.name));
    if (!main) {
      showError("open: choose a .json scene or a .gltf / .glb model (got " + files.map((f) => f.name).join(", ") + ")");
      return;
    }
    const next = cloneState(state);
    for (const name of [...next.overrides.keys()]) {
      const o = optionByName.get(name);
      if (o && o.sets && !VIEW_ONLY.has(name)) next.overrides.delete(name);
    }
    next.input = USER + "/" + main.name;
    next.preset = 0;
    next.file = main.name;
    clearProbe();
    const r = applyState(next);
    if (!r.error && !(r.warnings || []).length) note("opened " + main.name + " (a link cannot carry a file: it names the options only)", 6);
  }
  let dragDepth = 0;
  document.addEventListener("dragenter", (e) => { e.preventDefault(); dragDepth++; $("#drop").hidden = false; });
  document.addEventListener("dragleave", () => { if (--dragDepth <= 0) { dragDepth = 0; $("#drop").hidden = true; } });
  document.addEventListener("dragover", (e) => e.preventDefault());
  document.addEventListener("drop", (e) => {
    e.preventDefault();
    dragDepth = 0;
    $("#drop").hidden = true;
    if (Module.calledRun && e.dataTransfer) openFiles([...e.dataTransfer.files]);
  });

  // ---------------------------------------------------------------------------------------------
  // Keys: the key table (core/ui/controls.hpp) as sl_describe() gives it.
  // What some commands do in a browser, where it differs from the desktop viewer.
  const WEB_NOTE = {
    "ui-larger": "the browser's zoom (the page scales with it)",
    "ui-smaller": "the browser's zoom",
    "ui-as-monitor": "the browser's zoom back to 100%",
    "reload-shaders": "nothing to reload: the page's shaders are built in",
    "screenshot": "a PNG download of the view",
    "record": "a WebM download (the browser's MediaRecorder)",
    "play-pause": "the page plays no --animate animation",
    "quit": "close the browser tab",
    "light-markers": "the 3D light crosses (overlay \"lights\")",
    "intersection": "not in the page: the desktop viewer and shadelab --probe X,Y --intersection draw it",
  };
  // Mouse rows (no command) the page does otherwise.
  const WEB_ROW_NOTE = { "drag a light marker": "not in the page: the Lights section sets positions" };
  function keysTable() {
    const table = el("table", { class: "keys" });
    for (const c of D.controls) {
      const web = c.keys.map((k) => WEB_NOTE[k.command]).filter((x) => x).concat(WEB_ROW_NOTE[c.input] ? [WEB_ROW_NOTE[c.input]] : []);
      const action = c.action + (web.length ? " \u2014 here: " + [...new Set(web)].join("; ") : "");
      table.append(el("tr", {}, el("th", { text: c.input.replace(/\s{2,}/g, "  ") }), el("td", { text: action })));
    }
    return table;
  }
  function buildHelp() {
    const help = $("#help");
    help.textContent = "";
    const close = el("button", { type: "button", class: "close", text: "\u00d7", "aria-label": "close the help (Esc)" });
    close.addEventListener("click", () => toggleHelp(false));
    help.append(el("div", { class: "help-head" }, el("h2", { text: "shadelab " + D.version + ": keys and mouse" }), close));
    help.append(keysTable());
    help.append(el("p", { class: "hint", text: "Keys act when no text field has the focus. Ctrl+= / Ctrl+- / Ctrl+0 are left to the browser: its zoom scales the page. F1 or ? closes this help, so does Esc." }));
  }
  function toggleHelp(show) {
    const help = $("#help");
    help.hidden = show === undefined ? !help.hidden : !show;
  }
  function isTextField(t) {
    if (!t || !t.tagName) return false;
    if (t.tagName === "TEXTAREA" || t.tagName === "SELECT" || t.isContentEditable) return true;
    if (t.tagName !== "INPUT") return false;
    return !["checkbox", "radio", "range", "button", "submit", "color", "file", "reset"].includes(t.type);
  }
  function bindingOf(e) {
    const ctrl = e.ctrlKey || e.metaKey;
    for (const c of D.controls) {
      for (const b of c.keys) {
        if (b.characters) {
          if (!ctrl && !e.altKey && e.key.length === 1 && b.characters.includes(e.key)) return b;
        } else if (b.key && (e.key === b.key || (b.key.length === 1 && e.key.toLowerCase() === b.key))) {
          if (b.anyMods || b.ctrl === ctrl) return b;
        }
      }
    }
    return null;
  }
  const WIDGET_KEYS = new Set(["Tab", " ", "ArrowLeft", "ArrowRight", "ArrowUp", "ArrowDown", "Home", "End", "PageUp", "PageDown", "Enter"]);
  document.addEventListener("keydown", (e) => {
    if (!D || !Module.calledRun) return;
    const b = bindingOf(e);
    if (!b) return;
    if (b.command.startsWith("ui-")) return;  // Ctrl+= / Ctrl+- / Ctrl+0: the browser's zoom
    const t = document.activeElement;
    const inPanel = t && t !== document.body && t !== canvas && t !== document.documentElement;
    if (isTextField(t)) {
      // A text field keeps the keys but those that act while typing (Page Down / Up, Esc).
      if (!b.whileTyping) return;
      if (b.command === "escape") t.blur();
    } else if (inPanel && WIDGET_KEYS.has(e.key) && !b.whileTyping) {
      return;  // a slider, a checkbox or a button uses it
    }
    e.preventDefault();
    run(b.command, e);
  });
  function run(command) {
    const set = (name, value) => setOverride(name, value);
    switch (command) {
      case "flat": case "gouraud": case "phong": {
        const next = cloneState(state);
        next.overrides.set("layout", "single");
        next.overrides.set("shading", command);
        return applyState(next);
      }
      case "compare": return set("layout", "compare");
      case "difference": return set("layout", "diff");
      case "wireframe": case "vertex-normals": case "face-normals":
        return toggleOverlay(command, !overlaysOn().includes(command));
      case "light-markers": return toggleOverlay("lights", !overlaysOn().includes("lights"));
      case "formula": return set("formula", state.overrides.has("formula") ? null : true);
      case "shader": {
        const d = $("#section-shader");
        d.open = true;
        showPanel(true);
        $("#panel").scrollTop = d.offsetTop - $("#panel").offsetTop;  // scrollIntoView would scroll the page too
        return showShader();
      }
      case "reset-camera": return camera("reset");
      case "frame-model": return camera("frame");
      case "next-preset": return choosePreset(state.preset + 1);
      case "previous-preset": return choosePreset(state.preset ? state.preset - 1 : 1);
      case "first-preset": return choosePreset(1);
      case "last-preset": return choosePreset(D.presets.length);
      case "reset-preset":
        if (state.preset) {
          choosePreset(state.preset);
          return camera("reset");  // the same file: the program keeps the document, the camera goes back
        }
        return note("Backspace resets a lecture preset: none is shown", 4);
      case "toggle-panel": return showPanel(state.overrides.has("hide-panel"));
      case "fullscreen":
        if (document.fullscreenElement) return document.exitFullscreen();
        if (document.documentElement.requestFullscreen)
          return document.documentElement.requestFullscreen().catch((err) => note("fullscreen: " + err.message, 4));
        return note("fullscreen: this browser offers none", 4);
      case "help": return toggleHelp();
      case "reload-shaders": return note("F5: the page's shaders are built in, there is nothing to reload (the browser's reload is Ctrl+F5)", 6);
      case "screenshot": return screenshot();
      case "play-pause": return note("Space: no animation here (--animate plays in the desktop viewer and in videos from shadelab --output)", 6);
      case "record": return record();
      case "escape":
        if (!$("#help").hidden) return toggleHelp(false);
        if (document.querySelector("canvas[data-plot].big")) {
          document.querySelector("canvas[data-plot].big").classList.remove("big");
          return drawPlots();
        }
        return clearProbe();
      case "quit": return note("Q: close the browser tab to quit", 4);
      case "intersection": return note("I: the intersection diagram is the desktop viewer's (and shadelab --probe X,Y --intersection)", 6);
    }
  }
  function showPanel(show) {
    const was = !state.overrides.has("hide-panel");
    if (show) state.overrides.delete("hide-panel");
    else state.overrides.set("hide-panel", true);
    document.body.classList.toggle("panel-hidden", !show);
    followAddress();
    if (was !== show) layoutCanvas();
  }

  // ---------------------------------------------------------------------------------------------
  // The playlist's bar.
  function buildPlaylist() {
    const select = $("#preset");
    select.textContent = "";
    select.append(el("option", { value: "0", text: "\u2014 the built-in scene \u2014", hidden: true }));
    D.presets.forEach((p, i) => select.append(el("option", { value: String(i + 1), text: (i + 1) + ". " + p.title })));
    select.append(el("option", { value: "file", text: "file", hidden: true }));
    select.addEventListener("change", () => {
      const n = parseInt(select.value, 10);
      if (n >= 1) choosePreset(n);
      canvas.focus({ preventScroll: true });  // the keys act on the view again (1, 2, 3, C ...)
    });
    // The bar's buttons give the keyboard back to the view (arrows, Space, 1, 2, 3 ...).
    const back = (f) => () => { f(); canvas.focus({ preventScroll: true }); };
    $("#previous").addEventListener("click", back(() => run("previous-preset")));
    $("#next").addEventListener("click", back(() => run("next-preset")));
    $("#screenshot").addEventListener("click", back(screenshot));
    $("#record").addEventListener("click", back(record));
    $("#help-button").addEventListener("click", () => toggleHelp());
  }

  // ---------------------------------------------------------------------------------------------
  // The test hook (tests/web/test_web.py).
  const hook = {
    ready: false,
    frames: 0,
    lastError: "",
    probe: null,
    state: () => argsOf(state),
    apply: (args) => {
      // A whole command line: its first item, unless an option, is the input.
      const next = { input: null, preset: 0, file: "", overrides: new Map() };
      const list = (args || []).map(String);
      let i = 0;
      if (list.length && !list[0].startsWith("-")) {
        next.input = list[0];
        const at = D.presets.findIndex((p) => p.path === next.input);
        next.preset = at + 1;
        i = 1;
      }
      for (; i < list.length; i++) {
        const name = list[i].replace(/^--?/, "");
        const o = optionByName.get(name);
        if (!o) return applyState({ input: next.input, preset: next.preset, file: "", overrides: new Map([[name, true]]) });
        if (!o.argument) next.overrides.set(name, true);
        else if (name === "light") next.overrides.set(name, (next.overrides.get(name) || []).concat([list[++i]]));
        else next.overrides.set(name, list[++i]);
      }
      clearProbe();
      return applyState(next);
    },
    readPixels: () => {
      const r = callJson("sl_read_pixels");
      if (r.error) return r;
      const at = Module.ccall("sl_frame_data", "number", [], []);
      const bytes = Module.HEAPU8.subarray(at, at + r.width * r.height * 4);
      let text = "";
      for (let i = 0; i < bytes.length; i += 0x8000) text += String.fromCharCode.apply(null, bytes.subarray(i, i + 0x8000));
      return { width: r.width, height: r.height, base64: btoa(text) };
    },
    describe: null,  // sl_describe(): an object, and also callable (shadelab.describe().presets)
    probeAt: (x, y) => probe(x, y),
  };
  window.shadelab = hook;

  // ---------------------------------------------------------------------------------------------
  // Start: the module is loaded and main() has made the WebGL2 context.
  function start() {
    const gl = callJson("sl_gl_info");
    if (gl.error) {
      shadelabFailed("this browser offers no WebGL2 (it is switched off, or the graphics driver is blocked: try another browser, or turn on hardware acceleration)");
      return;
    }
    D = callJson("sl_describe");
    optionByName = new Map(D.options.map((o) => [o.name.replace(/^--/, ""), o]));
    hook.describe = Object.assign(() => D, D);
    note("");
    const fromLink = stateFromQuery(location.search);
    state = fromLink.state;
    if (state.overrides.has("hide-panel")) document.body.classList.add("panel-hidden");
    buildPlaylist();
    buildPanel();
    buildHelp();
    // The canvas's size before the first scene, so that it is framed for the view.
    const box = $("#view").getBoundingClientRect(), dpr = window.devicePixelRatio || 1;
    callJson("sl_resize", ["number", "number"], [Math.max(16, Math.round(box.width * dpr)), Math.max(16, Math.round(box.height * dpr))]);
    let r = applyState(state);
    if (r.error) {
      // The link's options are refused: its input without them, else the built-in scene.
      const message = "link: " + r.error;
      const plain = { input: state.input, preset: state.preset, file: "", overrides: new Map() };
      r = applyState(plain);
      if (r.error) r = applyState({ input: null, preset: 0, file: "", overrides: new Map() });
      showError(message);
    }
    if (fromLink.problems.length) showError("link: " + fromLink.problems.join("; "));
    if (r.error) return;
    new ResizeObserver(() => layoutCanvas()).observe($("#view"));
    window.addEventListener("resize", layoutCanvas);
    requestFrame();
  }

  window.addEventListener("error", (e) => {
    if (!hook.ready) shadelabFailed(e.message || "an error in the page");
  });

  return {
    canvas,
    print: (text) => console.log(text),
    printErr: (text) => {
      console.warn(text);
      if (/^shadelab: warning: /.test(text)) warnings.push(text.replace(/^shadelab: /, ""));
      else if (/^shadelab: /.test(text)) showError(text.replace(/^shadelab: /, ""));
    },
    onAbort: (what) => shadelabFailed("the program stopped (" + what + ")"),
    postRun: [start],
  };
})();

if (!window.WebGL2RenderingContext) shadelabFailed("this browser has no WebGL2");
