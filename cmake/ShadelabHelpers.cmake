# Small helpers shared by shadelab's CMake files.

# shadelab_require(<find_package args...> PACKAGE <debian-package>)
# find_package with a configure error that names the Debian package to install.
macro(shadelab_require name)
  cmake_parse_arguments(_req "" "PACKAGE" "" ${ARGN})
  find_package(${name} ${_req_UNPARSED_ARGUMENTS} QUIET)
  if(NOT ${name}_FOUND)
    message(FATAL_ERROR "${name} not found: install the Debian package ${_req_PACKAGE} "
                        "(bash third_party/install-deps.sh installs everything shadelab needs)")
  endif()
endmacro()

# Warnings (and, with SHADELAB_SANITIZE, AddressSanitizer + UndefinedBehaviorSanitizer) for shadelab's
# own targets only; Debian's headers are system headers and stay quiet.
function(shadelab_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-sign-conversion)
  if(SHADELAB_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
  if(SHADELAB_SANITIZE OR SHADELAB_FUZZ)
    set(_san -fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer)
    if(SHADELAB_FUZZ)
      list(APPEND _san -fsanitize=fuzzer-no-link)
    endif()
    # GCC's -Wmaybe-uninitialized gives false positives inside libstdc++ under -fsanitize=address
    # (GCC documents that sanitizers can cause them); the normal build keeps the warning.
    if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
      list(APPEND _san -Wno-maybe-uninitialized)
    endif()
    target_compile_options(${target} PRIVATE ${_san})
    target_link_options(${target} PRIVATE ${_san})
  endif()
endfunction()

# shadelab_embed_files(<out.cpp> <symbol> <base_dir> <files...>)
# Generates a .cpp that defines `const shadelab::EmbeddedFile <symbol>[]` (name relative to base_dir,
# contents) so an installed binary needs no data files beside it.
set(_SHADELAB_EMBED_SCRIPT ${CMAKE_CURRENT_LIST_DIR}/EmbedFiles.cmake)
function(shadelab_embed_files out symbol base_dir)
  add_custom_command(
    OUTPUT ${out}
    COMMAND ${CMAKE_COMMAND} -DOUT=${out} -DSYMBOL=${symbol} -DBASE_DIR=${base_dir}
            "-DFILES=${ARGN}" -P ${_SHADELAB_EMBED_SCRIPT}
    DEPENDS ${ARGN} ${_SHADELAB_EMBED_SCRIPT}
    COMMENT "Embedding ${symbol}"
    VERBATIM)
endfunction()
