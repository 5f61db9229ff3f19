"use strict";
// placeholder (replaced by the panel)
var Module = {
  canvas: document.getElementById("canvas"),
  postRun: [function () {
    const describe = JSON.parse(Module.ccall("sl_describe", "string", [], []));
    console.log("presets", describe.presets.length);
    const args = [];
    const params = new URLSearchParams(location.search);
    for (const [k, v] of params) { args.push("--" + k); if (v !== "") args.push(v); }
    Module.ccall("sl_resize", "string", ["number", "number"], [640, 480]);
    const r = JSON.parse(Module.ccall("sl_apply", "string", ["string"], [JSON.stringify(args)]));
    if (r.error) { const m = document.getElementById("message"); m.textContent = r.error; m.hidden = false; }
    const e = JSON.parse(Module.ccall("sl_render", "string", [], []));
    if (e.error) console.error(e.error);
    document.title = "shadelab ready";
  }],
};
