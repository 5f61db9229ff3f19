// Media: the screenshot (PNG) and the recording (WebM) of the view as downloads, and the files a
// person opens or drops, written into the program's file system under /user and opened as the input.
import { page, cloneState, dropSceneOptions } from "./state.js";
import { running, callJson, applyState, showError, note, requestFrame } from "./program.js";
import { el } from "./controls.js";
import { canvas, clearProbe } from "./view.js";

const $ = (selector) => document.querySelector(selector);
const USER = "/user";

// ---------------------------------------------------------------------------------------------
// Screenshot and recording.
function stamp() {
  const d = new Date(), p = (n) => String(n).padStart(2, "0");
  return d.getFullYear() + p(d.getMonth() + 1) + p(d.getDate()) + "-" + p(d.getHours()) + p(d.getMinutes()) + p(d.getSeconds());
}
function baseName() {
  const { state, D } = page;
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
export function screenshot() {
  // The frame as it is now (the drawing buffer is preserved), an area light's sum refined to the end.
  let passes = 1;
  while (callJson("sl_render").progress && passes < 1024) passes++;
  const name = baseName() + ".png";
  canvas.toBlob((blob) => {
    if (!blob) return showError("screenshot: the browser gave no PNG of the canvas");
    download(blob, name);
    note("screenshot: " + name, 4);
  }, "image/png");
}
export function record() {
  if (page.recorder) {
    page.recorder.stop();
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
  r.onstop = () => recorded(chunks, name);
  r.start(1000);
  page.recorder = r;
  $("#record").textContent = "\u25cf stop recording";
  $("#record").classList.add("recording");
  note("recording the view to WebM (Ctrl+R or the button stops)");
  requestFrame();
}
function recorded(chunks, name) {
  page.recorder = null;
  $("#record").textContent = "record";
  $("#record").classList.remove("recording");
  download(new Blob(chunks, { type: "video/webm" }), name);
  note("recorded: " + name, 4);
}

// ---------------------------------------------------------------------------------------------
// Files: written into the program's file system under /user and opened as the input.
export async function openFiles(files) {
  if (!files.length) return;
  const FS = page.program.FS;
  try {
    try { FS.mkdir(USER); } catch (e) { /* it exists */ }
    for (const f of files) FS.writeFile(USER + "/" + f.name, new Uint8Array(await f.arrayBuffer()));
  } catch (e) {
    showError("could not read the file: " + (e && e.message ? e.message : e));
    return;
  }
  const main = files.find((f) => /\.json$/i.test(f.name)) || files.find((f) => /\.(gltf|glb)$/i.test(f.name));
  if (!main) {
    showError("open: choose a .json scene or a .gltf / .glb model (got " + files.map((f) => f.name).join(", ") + ")");
    return;
  }
  const next = cloneState(page.state);
  dropSceneOptions(next);
  next.input = USER + "/" + main.name;
  next.preset = 0;
  next.file = main.name;
  clearProbe();
  const r = applyState(next);
  if (!r.error && !(r.warnings || []).length) note("opened " + main.name + " (a link cannot carry a file: it names the options only)", 6);
}
export function bindDrop() {
  const drop = $("#drop");
  document.addEventListener("dragenter", (e) => { e.preventDefault(); page.dragDepth++; drop.hidden = false; });
  document.addEventListener("dragleave", () => { if (--page.dragDepth <= 0) { page.dragDepth = 0; drop.hidden = true; } });
  document.addEventListener("dragover", (e) => e.preventDefault());
  document.addEventListener("drop", (e) => {
    e.preventDefault();
    page.dragDepth = 0;
    drop.hidden = true;
    if (running() && e.dataTransfer) openFiles([...e.dataTransfer.files]);
  });
}
