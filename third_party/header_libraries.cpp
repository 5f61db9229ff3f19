// The implementations of the header-only libraries that the Linux build links from Debian's shared
// libraries (libtinygltf, libstb), compiled in for builds that have no such libraries: the Windows
// build (cmake/HostHeaderLibraries.cmake). tinygltf as Debian builds it: its stb_image, no Draco.
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_TRUETYPE_IMPLEMENTATION
#include <stb/stb_image.h>
#include <stb/stb_image_write.h>
#include <stb/stb_truetype.h>

// tiny_gltf.h would include <stb_image.h> and <stb_image_write.h> again, implementations and all.
#define TINYGLTF_NO_INCLUDE_STB_IMAGE
#define TINYGLTF_NO_INCLUDE_STB_IMAGE_WRITE
#define TINYGLTF_IMPLEMENTATION
#include <tiny_gltf.h>
