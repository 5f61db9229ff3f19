# The header-only libraries of the build machine's Debian packages, for a cross build (./dev
# test-windows, cmake/mingw-w64.cmake): GLM, nlohmann-json, stb and tinygltf's tiny_gltf.h compile for
# any target. Only those folders and that file reach the include path, through links in the build
# folder: /usr/include itself holds the build machine's C library headers, which must stay out.
# Defines glm::glm, nlohmann_json::nlohmann_json, TinyGLTF::TinyGLTF and SHADELAB_STB_LIBRARY, as the
# Linux build's Debian packages do.
set(SHADELAB_HOST_INCLUDE_DIR /usr/include CACHE PATH "Where the Debian header packages put their headers")
set(_host_headers ${CMAKE_BINARY_DIR}/host-headers)
file(MAKE_DIRECTORY ${_host_headers})
foreach(entry glm:libglm-dev nlohmann:nlohmann-json3-dev stb:libstb-dev tiny_gltf.h:libtinygltf-dev)
  string(REPLACE ":" ";" entry ${entry})
  list(GET entry 0 name)
  list(GET entry 1 package)
  if(NOT EXISTS ${SHADELAB_HOST_INCLUDE_DIR}/${name})
    message(FATAL_ERROR "${SHADELAB_HOST_INCLUDE_DIR}/${name} not found: install the Debian package ${package} "
                        "(bash third_party/install-deps.sh third_party/packages-windows.txt)")
  endif()
  file(CREATE_LINK ${SHADELAB_HOST_INCLUDE_DIR}/${name} ${_host_headers}/${name} SYMBOLIC)
endforeach()

add_library(shadelab_host_headers INTERFACE)
target_include_directories(shadelab_host_headers SYSTEM INTERFACE ${_host_headers})
add_library(glm::glm ALIAS shadelab_host_headers)
add_library(nlohmann_json::nlohmann_json ALIAS shadelab_host_headers)

# On Linux tinygltf and stb are Debian's shared libraries; here their implementations are compiled in.
add_library(shadelab_header_libraries STATIC ${PROJECT_SOURCE_DIR}/third_party/header_libraries.cpp)
target_link_libraries(shadelab_header_libraries PUBLIC shadelab_host_headers)
add_library(TinyGLTF::TinyGLTF ALIAS shadelab_header_libraries)
set(SHADELAB_STB_LIBRARY shadelab_header_libraries)
