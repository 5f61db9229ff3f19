#pragma once
// How deeply a JSON text nests, measured on the text itself, before any parser or serializer recurses
// over it (nlohmann's dump and tinygltf's value reader are recursive: 20,000 levels overflow the stack).
#include <cstddef>
#include <string>
#include <string_view>

namespace shadelab {

// Deepest nesting of objects and arrays in `text` (brackets inside strings do not count). Malformed
// text is measured as far as it goes; the parser reports what is wrong with it.
std::size_t jsonNestingDepth(std::string_view text);

// No JSON input (a scene, a glTF file, the viewer's settings) nests deeper than this; real files stay
// under 20 levels, the parsers used here are safe well beyond it.
inline constexpr std::size_t kMaxJsonDepth = 512;

// Throws InputError "<label>: JSON nested deeper than 512 levels" when `text` does.
void checkJsonDepth(std::string_view text, const std::string& label);

}  // namespace shadelab
