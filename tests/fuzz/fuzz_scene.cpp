// libFuzzer target: the scene-file parser. Any input either parses or is an InputError; a scene that
// parses must also survive a save/load round trip (what the viewer's "save scene" relies on).
#include "core/base/error.hpp"
#include "core/scene/scene_json.hpp"

#include <cstdint>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    shadelab::Scene scene;
    try {
        scene = shadelab::parseScene(text, "fuzz.json", "/nonexistent-shadelab-fuzz");
    } catch (const shadelab::InputError&) {
        return 0;
    }
    const std::string saved = shadelab::sceneToJson(scene, "/nonexistent-shadelab-fuzz");
    try {
        shadelab::parseScene(saved, "saved.json", "/nonexistent-shadelab-fuzz");
    } catch (const shadelab::InputError&) {
        std::abort();  // a scene shadelab accepted, saved by shadelab, must load again
    }
    return 0;
}
