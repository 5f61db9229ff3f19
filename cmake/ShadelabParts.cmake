# The parts of shadelab that need a GL stack, each an option that is on where what it needs is found:
#   SHADELAB_VIEWER  the interactive window: GLFW (libglfw3-dev) and Dear ImGui (libimgui-dev)
#   SHADELAB_OSMESA  the OSMesa headless context (libosmesa6-dev's headers; the library is dlopen'ed)
#   SHADELAB_EGL     the EGL headless context (libegl-dev's headers; dlopen'ed too)
# Any of them needs the glad loader generator (python3-glad) and builds the renderer. Asking for a part
# whose packages are missing (-DSHADELAB_EGL=ON) fails with their names; configure prints one line per
# part with what a missing one turns off. Sets SHADELAB_HEADLESS (OSMesa or EGL) and SHADELAB_RENDER
# (any part): the renderer, glad and the GL tests.

set(_parts_here ON)
if(CMAKE_CROSSCOMPILING OR CMAKE_SYSTEM_NAME STREQUAL "Windows")
  set(_parts_here OFF)   # the GL parts are Linux-only (README, "Windows"); don't find the build machine's
endif()

set(_missing_gl "")
set(_missing_viewer "")
set(_missing_osmesa "")
set(_missing_egl "")
if(_parts_here)
  find_program(GLAD_EXECUTABLE glad)
  if(NOT GLAD_EXECUTABLE)
    set(_missing_gl python3-glad)
  endif()
  find_package(glfw3 CONFIG QUIET)
  if(NOT glfw3_FOUND)
    list(APPEND _missing_viewer libglfw3-dev)
  endif()
  find_path(IMGUI_INCLUDE_DIR imgui.h PATH_SUFFIXES imgui)
  find_library(IMGUI_LIBRARY NAMES libimgui.a imgui)
  find_library(IMGUI_STB_LIBRARY stb)
  if(NOT IMGUI_INCLUDE_DIR OR NOT IMGUI_LIBRARY OR NOT IMGUI_STB_LIBRARY
     OR NOT EXISTS ${IMGUI_INCLUDE_DIR}/backends/imgui_impl_glfw.h)
    list(APPEND _missing_viewer libimgui-dev)
  endif()
  find_package(PkgConfig QUIET)
  if(PkgConfig_FOUND)
    pkg_check_modules(OSMESA QUIET osmesa)
    pkg_check_modules(EGL QUIET egl)
  endif()
  if(NOT OSMESA_FOUND)
    set(_missing_osmesa libosmesa6-dev)
  endif()
  if(NOT EGL_FOUND)
    set(_missing_egl libegl-dev)
  endif()
else()
  set(_missing_gl "a Linux GL stack")
endif()

# shadelab_part(VAR "description" "what it turns off" missing-packages...)
function(shadelab_part var description turns_off)
  set(missing ${_missing_gl} ${ARGN})
  if(missing)
    set(found OFF)
  else()
    set(found ON)
  endif()
  option(${var} "Build ${description} (on where found)" ${found})
  if(${var} AND missing)
    list(JOIN missing ", " names)
    message(FATAL_ERROR "${var} is ON but ${description} needs ${names}: install the Debian package(s) "
                        "(bash third_party/install-deps.sh), or configure with -D${var}=OFF")
  endif()
  if(${var})
    message(STATUS "shadelab: ${description}: ON")
  elseif(missing)
    list(JOIN missing ", " names)
    message(STATUS "shadelab: ${description}: OFF (not found: ${names}); without it ${turns_off}")
  else()
    message(STATUS "shadelab: ${description}: OFF (${var}=OFF); without it ${turns_off}")
  endif()
endfunction()

shadelab_part(SHADELAB_VIEWER "the viewer (GLFW, Dear ImGui)"
              "there is no window: shadelab renders only with --output, and the viewer tests are not built"
              ${_missing_viewer})
shadelab_part(SHADELAB_OSMESA "the OSMesa headless context"
              "--backend osmesa is refused and the GL tests on OSMesa are not built" ${_missing_osmesa})
shadelab_part(SHADELAB_EGL "the EGL headless context"
              "--backend egl is refused and the GL tests on EGL (gl.egl.*) are not built" ${_missing_egl})

if(SHADELAB_OSMESA OR SHADELAB_EGL)
  set(SHADELAB_HEADLESS ON)
else()
  set(SHADELAB_HEADLESS OFF)
  message(STATUS "shadelab: no headless context: --output, --benchmark and the other renders are refused, "
                 "and the GL and rendering CLI tests are not built")
endif()
if(SHADELAB_HEADLESS OR SHADELAB_VIEWER)
  set(SHADELAB_RENDER ON)
else()
  set(SHADELAB_RENDER OFF)
  message(STATUS "shadelab: core only: platform, core, the command line (--help, --version, --plot, --info) "
                 "and the unit tests")
endif()
