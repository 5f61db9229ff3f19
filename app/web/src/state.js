// The page's state, in one object (`page`, imported by every other file: no file keeps mutable
// variables of its own), and the link: the state <-> the command line <-> the URL query.
//
// The state is a command line: the input (null: the built-in scene), the preset it is (1-based, 0:
// none), the options given after it. The link's query parameters are the same options by their names
// (?preset=6&layout=compare&ke=128); sl_apply() reads them with the parser of the `shadelab` program.

// A state with no input and no options.
export function emptyState() {
  // overrides: name -> true (a switch), a string, or a list (light).
  return { input: null, preset: 0, file: "", overrides: new Map() };
}

export const page = {
  program: null,        // the emscripten module instance (createShadelab's): ccall, HEAPU8, FS, calledRun
  D: null,              // sl_describe()
  result: null,         // the last successful sl_apply(): {scene, title, caption, panes, ...}
  optionByName: new Map(),  // "ke" -> the option table's row
  state: emptyState(),  // the state drawn
  probeAt: null,        // [x, y] canvas pixels of the probe shown
  recorder: null,       // the MediaRecorder while recording
  controls: [],         // {update()} of every panel control
  warnings: [],         // the program's "shadelab: warning: ..." lines since the last sl_apply()
  sectionBodies: {},    // section name -> its <div class="body">
  noteTimer: 0,         // hides #note
  framePending: false,  // a frame is asked for on the next animation frame
  pendingOverride: null,  // [name, value, input] of a slider, applied on the next animation frame
  drag: null,           // the pointer press or drag over the canvas
  dragDepth: 0,         // dragenter minus dragleave of files over the page
  uid: 0,               // the last generated element id ("c1", "c2" ...)
  // The test and embedding hook, window.shadelab (start.js adds its functions).
  // progress: [passes done, passes] while a sampled area light's sum refines, else null.
  hook: { ready: false, frames: 0, lastError: "", probe: null, describe: null, module: null, progress: null },
};

// Kept when the preset changes, like the options that set no scene field.
const VIEW_ONLY = new Set(["size"]);

function optionOrder(name) {
  const o = page.optionByName.get(name);
  return o ? page.D.options.indexOf(o) : 1e9;
}
function sortedNames(s) {
  return [...s.overrides.keys()].sort((a, b) => optionOrder(a) - optionOrder(b));
}

// The state as the program's command line.
export function argsOf(s) {
  const args = s.input ? [s.input] : [];
  for (const name of sortedNames(s)) {
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
// The state as the link's query.
export function queryOf(s) {
  const parts = [];
  if (s.preset) parts.push("preset=" + s.preset);
  for (const name of sortedNames(s)) {
    const v = s.overrides.get(name);
    if (v === true) parts.push(encode(name));
    else if (Array.isArray(v)) for (const item of v) parts.push(encode(name) + "=" + encode(item));
    else parts.push(encode(name) + "=" + encode(v));
  }
  return parts.length ? "?" + parts.join("&") : "";
}
export function followAddress() {
  const url = location.pathname + queryOf(page.state) + location.hash;
  try {
    history.replaceState(null, "", url);
  } catch (e) {
    // file:// in some browsers refuses replaceState: the panel still works.
  }
}
// The link's parameters as a state; errors name the parameter.
export function stateFromQuery(search) {
  const s = emptyState();
  const problems = [];
  const D = page.D;
  for (const [key, value] of new URLSearchParams(search)) {
    if (key === "preset") {
      const n = parseInt(value, 10);
      if (n >= 1 && n <= D.presets.length) {
        s.preset = n;
        s.input = D.presets[n - 1].path;
      } else problems.push("preset=" + value + ": there are presets 1.." + D.presets.length);
      continue;
    }
    const o = page.optionByName.get(key);
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
export function cloneState(s) {
  const o = new Map();
  for (const [k, v] of s.overrides) o.set(k, Array.isArray(v) ? v.slice() : v);
  return { input: s.input, preset: s.preset, file: s.file, overrides: o };
}
// Drops the options that set a scene field (not the view's): another input comes.
export function dropSceneOptions(s) {
  for (const name of [...s.overrides.keys()]) {
    const o = page.optionByName.get(name);
    if (o && o.sets && !VIEW_ONLY.has(name)) s.overrides.delete(name);
  }
}

// The scene's value at an option's `sets` path: "objects[].material.ke" is the first object's
// (a scene of one object writes it at the top: "material.ke"); "diff.a, diff.b" joins both.
export function sceneValue(scene, sets) {
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
export function shownValue(name, fallback) {
  const state = page.state;
  if (state.overrides.has(name)) return state.overrides.get(name);
  const o = page.optionByName.get(name);
  const v = o && o.sets && page.result ? sceneValue(page.result.scene, o.sets) : undefined;
  return v === undefined ? fallback : v;
}
