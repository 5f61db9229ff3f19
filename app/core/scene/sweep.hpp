#pragma once
// Sweep sheets: `--sweep ke=1,8,32,128,512` renders one tile per value of a scene parameter, two
// sweeps a grid (the first along the columns, the second along the rows). GL-free: parsing, applying
// a value to a scene, and composing the labelled sheet; headless/headless.cpp renders the tiles.
#include "core/image/image.hpp"
#include "core/scene/scene.hpp"

#include <string>
#include <vector>

namespace shadelab {

// The parameters a sweep can vary. Numbers apply to every object (ke, ks, kd, ka), every light
// (intensity) or the first object's mesh (tessellation: uvsphere slices = n and stacks = n / 2,
// icosphere subdivisions, torus segments n and n / 2, plane subdivisions); names to the scene.
struct Sweep {
    std::string parameter;            // ke | ks | kd | ka | intensity | tessellation | ior | shading | reflection |
                                      // specular_normalization | fresnel
    std::vector<std::string> values;  // as written, each already checked
};
inline constexpr int kMaxSweeps = 2;
inline constexpr std::size_t kMaxSweepValues = 32;

// "PARAM=V1,V2,..." -> Sweep. Throws InputError "FLAG: what" for an unknown parameter, a value that
// is not a number (or name) or out of the parameter's range, or an empty or too long list.
Sweep parseSweep(const std::string& text, const std::string& flag);
// Sets value `index` of the sweep on the scene. Throws InputError (a tessellation sweep on a cube or
// glTF model; values are checked by parseSweep).
void applySweep(Scene& scene, const Sweep& sweep, std::size_t index, const std::string& flag);
// What a parameter's values are: numbers, whole numbers (tessellation) or names (shading); Unknown for
// a name that is no parameter. --animate's ramps (core/scene/animation.hpp) interpolate the numbers.
enum class SweepValues { Number, Integer, Name, Unknown };
SweepValues sweepValues(const std::string& parameter);
// "k_e=32", "shading=phong".
std::string sweepLabel(const Sweep& sweep, std::size_t index);

// Tiles in a grid of `columns`, row by row, each with its label in a bar above it. All tiles have
// the same size. Background and label colours suit a projector (dark grey, white text). Labels are
// drawn at kSheetLabelScale when every label fits its tile, else at scale 1 (one still too long is cut).
Image contactSheet(const std::vector<Image>& tiles, const std::vector<std::string>& labels, int columns);
inline constexpr int kSheetLabelScale = 2;  // font pixels per image pixel of the labels

}  // namespace shadelab
