# The parts of shadelab that need a GL stack, each an option that is on where what it needs is found:
#   SHADELAB_VIEWER  the interactive window: GLFW (libglfw3-dev) and Dear ImGui (libimgui-dev)
#   SHADELAB_OSMESA  the OSMesa headless context (libosmesa6-dev's headers; the library is dlopen'ed)
#   SHADELAB_EGL     the EGL headless context (libegl-dev's headers; dlopen'ed too)
# Any of them needs the glad loader generator (python3-glad) and builds the renderer. Asking for a part
# whose packages are missing (-DSHADELAB_EGL=ON) fails with their names; configure prints one line per
# part with what a missing one turns off. Sets SHADELAB_HEADLESS (OSMesa or EGL) and SHADELAB_RENDER
# (any part): the renderer, glad and the GL tests.

set(_parts_here ON)
# The web build (emcmake cmake, ./dev web): the renderer on WebGL2 and the page's front end (app/web);
# none of the Linux parts.
if(EMSCRIPTEN)
  set(SHADELAB_WEB ON)
else()
  set(SHADELAB_WEB OFF)
endif()
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
elseif(SHADELAB_WEB)
  set(_missing_gl "a Linux GL stack (the web build has WebGL2 instead)")
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
if(SHADELAB_WEB)
  message(STATUS "shadelab: the web page (WebGL2, app/web): ON")
endif()
if(SHADELAB_HEADLESS OR SHADELAB_VIEWER OR SHADELAB_WEB)
  set(SHADELAB_RENDER ON)
else()
  set(SHADELAB_RENDER OFF)
  message(STATUS "shadelab: core only: platform, core, the command line (--help, --version, --plot, --info) "
                 "and the unit tests")
endif()

# SHADELAB_VIDEO  videos (--animate --output FILE.gif|.mp4|.webm): Debian's FFmpeg libraries through
#                 pkg-config (libavcodec-dev, libavformat-dev, libswscale-dev, libavutil-dev). GL-free
#                 itself (app/video); the program renders the frames with a headless context.
set(_missing_video "")
if(_parts_here)
  find_package(PkgConfig QUIET)
  if(PkgConfig_FOUND)
    pkg_check_modules(LIBAV QUIET IMPORTED_TARGET libavcodec libavformat libswscale libavutil)
  endif()
  if(NOT LIBAV_FOUND)
    set(_missing_video libavcodec-dev libavformat-dev libswscale-dev libavutil-dev)
  endif()
else()
  set(_missing_video "FFmpeg's libraries (Linux)")
endif()
if(_missing_video)
  set(_video_found OFF)
else()
  set(_video_found ON)
endif()
option(SHADELAB_VIDEO "Build video encoding (FFmpeg's libraries; on where found)" ${_video_found})
if(SHADELAB_VIDEO AND _missing_video)
  list(JOIN _missing_video ", " _names)
  message(FATAL_ERROR "SHADELAB_VIDEO is ON but video encoding needs ${_names}: install the Debian package(s) "
                      "(bash third_party/install-deps.sh), or configure with -DSHADELAB_VIDEO=OFF")
endif()
if(SHADELAB_VIDEO)
  message(STATUS "shadelab: video encoding (FFmpeg's libraries): ON")
else()
  message(STATUS "shadelab: video encoding: OFF; without it --animate --output FILE.gif|.mp4|.webm is refused")
endif()

# SHADELAB_PYTHON  the Python module `shadelab` (app/python, README "Python"): pybind11 (pybind11-dev) and the
#                  headers of the interpreter it is built for (python3-dev): Debian's /usr/bin/python3 unless
#                  -DPython3_EXECUTABLE=... names another. Renders in-process on a headless context, so
#                  it is built where one is (SHADELAB_OSMESA or SHADELAB_EGL); numpy (python3-numpy) is
#                  needed when it runs. Everything it links is then compiled as position-independent code.
set(_missing_python "")
if(SHADELAB_SANITIZE OR SHADELAB_FUZZ)
  # An instrumented module needs its sanitizer's runtime loaded before the interpreter's own libraries.
  set(_missing_python "a build without sanitizers (SHADELAB_SANITIZE, SHADELAB_FUZZ)")
elseif(_parts_here AND SHADELAB_HEADLESS)
  if(NOT DEFINED Python3_EXECUTABLE AND EXISTS /usr/bin/python3)
    set(Python3_EXECUTABLE /usr/bin/python3)
  endif()
  find_package(Python3 COMPONENTS Interpreter Development.Module QUIET)
  if(NOT Python3_Development.Module_FOUND)
    list(APPEND _missing_python python3-dev)
  endif()
  find_package(pybind11 CONFIG QUIET)
  if(NOT pybind11_FOUND)
    list(APPEND _missing_python pybind11-dev)
  endif()
elseif(_parts_here)
  set(_missing_python "a headless context (SHADELAB_OSMESA or SHADELAB_EGL)")
else()
  set(_missing_python "a Linux build")
endif()
shadelab_part(SHADELAB_PYTHON "the Python module (pybind11, ${Python3_EXECUTABLE})"
              "there is no `import shadelab` and its tests are not built" ${_missing_python})
if(SHADELAB_PYTHON)
  set(CMAKE_POSITION_INDEPENDENT_CODE ON)
endif()
