#pragma once
// The command line's shorthands for a mesh (--mesh) and a light (--light): read, and written back. What
// parseLightShorthand reads from lightShorthand(l) is l again (every number written with the digits
// that read back to the same float), so the web page and the Python module print a light or mesh the
// panel edited as the option that sets it, and the link carries it.
#include "core/scene/scene.hpp"

#include <string>

namespace shadelab {

// Parses the command line's mesh shorthand: "uvsphere[:slices[:stacks]]", "icosphere[:subdivisions]",
// "torus[:major_segments[:minor_segments]]", "cube", "plane[:subdivisions]", or a .gltf/.glb path.
MeshSpec parseMeshShorthand(const std::string& text, const std::string& optionName);

// Parses the command line's light shorthand, TYPE:X,Y,Z[:KEY=VALUE]...:
//   point:X,Y,Z        a point light at (X, Y, Z)
//   directional:X,Y,Z  a directional light travelling along (X, Y, Z)
//   area:X,Y,Z         an area light centred at (X, Y, Z)
// and the keys color=R,G,B  intensity=I  attenuation=none|inverse-square  range=R (point, area)
// normal=X,Y,Z  size=W,H  samples=NXxNY  two-sided (area). E.g.
//   area:0,3,0:size=1.6,1.6:samples=8x8:intensity=9:attenuation=inverse-square
// Values are checked against the scene format's ranges; errors are InputErrors "<optionName>: ...".
Light parseLightShorthand(const std::string& text, const std::string& optionName);

// The --mesh shorthand of a mesh: "uvsphere:64:32", "icosphere:3", "torus:48:24", "cube", "plane:1", or a
// glTF model's path as written. The shorthand has no sizes: a cube's or sphere's size is the default's.
std::string meshShorthand(const MeshSpec& mesh);

// The --light shorthand of a light: TYPE:X,Y,Z, then each key whose value differs from what the shorthand
// gives when the key is left out (an untouched point light is "point:X,Y,Z").
std::string lightShorthand(const Light& light);

// A number as the shorthands write it: the fewest digits that read back (strtof) to the same float.
std::string shortestNumber(float value);

}  // namespace shadelab
