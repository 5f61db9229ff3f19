#pragma once
// Reading and writing scene files (JSON). The format is documented in the README ("Scene file").
// Every field is optional; unknown fields, wrong types and out-of-range values are InputErrors whose
// message names the file and the field, e.g. "a.json: lights[0].intensity: must be >= 0 (got -1)".
#include "core/scene/scene.hpp"

#include <string>

namespace shadelab {

// Parses scene JSON. `fileLabel` prefixes error messages; relative glTF paths resolve against `baseDir`.
Scene parseScene(const std::string& text, const std::string& fileLabel, const std::string& baseDir);

// Reads and parses a scene file.
Scene loadSceneFile(const std::string& path);

// The built-in default scene (assets/scenes/default.json, embedded at build time).
Scene defaultScene();

// A scene that shows one glTF/GLB model with everything else at its defaults (camera auto-framed).
Scene sceneForModel(const std::string& modelPath);

// Serialises every field of the scene, so loading the result gives the same image. glTF paths are
// written relative to `saveDir` (the folder the JSON will be saved in).
std::string sceneToJson(const Scene& scene, const std::string& saveDir);

// One light or one mesh as a scene file writes it ("lights"[i], "mesh"), read and checked as the scene
// reader does; `label` starts the messages. The web page's panel edits lights and meshes as JSON.
Light lightFromJson(const std::string& text, const std::string& label);
MeshSpec meshFromJson(const std::string& text, const std::string& label);

// Validation shared with the command line; each throws InputError "<where>: <what>".
// "all" | "ambient" | "diffuse" | "specular" | "light:N" (0 <= N < kMaxLights) | "unlit". Throws
// InputError "WHERE: what" (no prefix when `where` is empty). Whether light N exists is the caller's check.
TermView parseTermView(const std::string& text, const std::string& where);

void checkCoefficients(const Material& m, const std::string& where);
// "environment" and --environment: "room", "sky", "none", or an image file (relative to baseDir),
// read here. InputError "WHERE: ..." naming what is wrong.
EnvironmentSpec parseEnvironment(const std::string& text, const std::string& baseDir, const std::string& where);
// InputError "WHEREanisotropy: ..." when an object's material is anisotropic under reflection phong
// (Ashikhmin and Shirley's lobe is Blinn-Phong's, about H).
void checkAnisotropy(const Scene& scene, const std::string& where);
void checkImageSize(int width, int height, const std::string& where);

}  // namespace shadelab
