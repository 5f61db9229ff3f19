// The keys: the key table (core/ui/controls.hpp) as sl_describe() gives it, the help dialog, the
// keydown handler, the commands it runs (run), and the bar's playlist and buttons that run them too.
import { page, cloneState, followAddress } from "./state.js";
import { running, applyState, setOverride, choosePreset, note } from "./program.js";
import { el } from "./controls.js";
import { overlaysOn, toggleOverlay, showShader, drawPlots } from "./sections.js";
import { canvas, camera, clearProbe, layoutCanvas } from "./view.js";
import { screenshot, record } from "./media.js";

const $ = (selector) => document.querySelector(selector);

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
export function keysTable() {
  const table = el("table", { class: "keys" });
  for (const c of page.D.controls) {
    const web = c.keys.map((k) => WEB_NOTE[k.command]).filter((x) => x).concat(WEB_ROW_NOTE[c.input] ? [WEB_ROW_NOTE[c.input]] : []);
    const action = c.action + (web.length ? " \u2014 here: " + [...new Set(web)].join("; ") : "");
    table.append(el("tr", {}, el("th", { text: c.input.replace(/\s{2,}/g, "  ") }), el("td", { text: action })));
  }
  return table;
}
export function buildHelp() {
  const help = $("#help");
  help.textContent = "";
  const close = el("button", { type: "button", class: "close", text: "\u00d7", "aria-label": "close the help (Esc)" });
  close.addEventListener("click", () => toggleHelp(false));
  help.append(el("div", { class: "help-head" }, el("h2", { text: "shadelab " + page.D.version + ": keys and mouse" }), close));
  help.append(keysTable());
  help.append(el("p", { class: "hint", text: "Keys act when no text field has the focus. Ctrl+= / Ctrl+- / Ctrl+0 are left to the browser: its zoom scales the page. F1 or ? closes this help, so does Esc." }));
}
function toggleHelp(show) {
  const help = $("#help");
  help.hidden = show === undefined ? !help.hidden : !show;
}

// ---------------------------------------------------------------------------------------------
// keydown: the binding of the key table, unless a text field or a widget of the panel uses the key.
function isTextField(t) {
  if (!t || !t.tagName) return false;
  if (t.tagName === "TEXTAREA" || t.tagName === "SELECT" || t.isContentEditable) return true;
  if (t.tagName !== "INPUT") return false;
  return !["checkbox", "radio", "range", "button", "submit", "color", "file", "reset"].includes(t.type);
}
function bindingOf(e) {
  const ctrl = e.ctrlKey || e.metaKey;
  for (const c of page.D.controls) {
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
function keyDown(e) {
  if (!page.D || !running()) return;
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
}
export function bindKeys() {
  document.addEventListener("keydown", keyDown);
}

// ---------------------------------------------------------------------------------------------
// The commands of the key table, as the page carries them out.
const set = (name, value) => setOverride(name, value);
const overlay = (name) => toggleOverlay(name, !overlaysOn().includes(name));
function single(mode) {
  const next = cloneState(page.state);
  next.overrides.set("layout", "single");
  next.overrides.set("shading", mode);
  return applyState(next);
}
function openShader() {
  const d = $("#section-shader");
  d.open = true;
  showPanel(true);
  $("#panel").scrollTop = d.offsetTop - $("#panel").offsetTop;  // scrollIntoView would scroll the page too
  return showShader();
}
function resetPreset() {
  if (page.state.preset) {
    choosePreset(page.state.preset);
    return camera("reset");  // the same file: the program keeps the document, the camera goes back
  }
  return note("Backspace resets a lecture preset: none is shown", 4);
}
function fullscreen() {
  if (document.fullscreenElement) return document.exitFullscreen();
  if (document.documentElement.requestFullscreen)
    return document.documentElement.requestFullscreen().catch((err) => note("fullscreen: " + err.message, 4));
  return note("fullscreen: this browser offers none", 4);
}
function escape() {
  if (!$("#help").hidden) return toggleHelp(false);
  if (document.querySelector("canvas[data-plot].big")) {
    document.querySelector("canvas[data-plot].big").classList.remove("big");
    return drawPlots();
  }
  return clearProbe();
}
const COMMANDS = {
  "flat": () => single("flat"),
  "gouraud": () => single("gouraud"),
  "phong": () => single("phong"),
  "compare": () => set("layout", "compare"),
  "difference": () => set("layout", "diff"),
  "wireframe": () => overlay("wireframe"),
  "vertex-normals": () => overlay("vertex-normals"),
  "face-normals": () => overlay("face-normals"),
  "light-markers": () => overlay("lights"),
  "formula": () => set("formula", page.state.overrides.has("formula") ? null : true),
  "shader": openShader,
  "reset-camera": () => camera("reset"),
  "frame-model": () => camera("frame"),
  "next-preset": () => choosePreset(page.state.preset + 1),
  "previous-preset": () => choosePreset(page.state.preset ? page.state.preset - 1 : 1),
  "first-preset": () => choosePreset(1),
  "last-preset": () => choosePreset(page.D.presets.length),
  "reset-preset": resetPreset,
  "toggle-panel": () => showPanel(page.state.overrides.has("hide-panel")),
  "fullscreen": fullscreen,
  "help": () => toggleHelp(),
  "reload-shaders": () => note("F5: the page's shaders are built in, there is nothing to reload (the browser's reload is Ctrl+F5)", 6),
  "screenshot": () => screenshot(),
  "play-pause": () => note("Space: no animation here (--animate plays in the desktop viewer and in videos from shadelab --output)", 6),
  "record": () => record(),
  "escape": escape,
  "quit": () => note("Q: close the browser tab to quit", 4),
  "intersection": () => note("I: the intersection diagram is the desktop viewer's (and shadelab --probe X,Y --intersection)", 6),
};
export function run(command) {
  return Object.prototype.hasOwnProperty.call(COMMANDS, command) ? COMMANDS[command]() : undefined;
}
function showPanel(show) {
  const state = page.state;
  const was = !state.overrides.has("hide-panel");
  if (show) state.overrides.delete("hide-panel");
  else state.overrides.set("hide-panel", true);
  document.body.classList.toggle("panel-hidden", !show);
  followAddress();
  if (was !== show) layoutCanvas();
}

// ---------------------------------------------------------------------------------------------
// The playlist's bar.
export function buildPlaylist() {
  const select = $("#preset");
  select.textContent = "";
  select.append(el("option", { value: "0", text: "\u2014 the built-in scene \u2014", hidden: true }));
  page.D.presets.forEach((p, i) => select.append(el("option", { value: String(i + 1), text: (i + 1) + ". " + p.title })));
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
