# CMake toolchain for 64-bit Windows with Debian's MinGW-w64 (g++-mingw-w64-x86-64-posix): ./dev
# test-windows builds platform, core, the command-line parser and the unit tests with it and runs them
# under wine64. The header libraries come from the build machine (cmake/HostHeaderLibraries.cmake).
set(CMAKE_SYSTEM_NAME Windows)
set(CMAKE_SYSTEM_PROCESSOR x86_64)
set(_mingw x86_64-w64-mingw32)
# The posix variant: std::thread and std::mutex through winpthreads (the win32 variant has neither).
set(CMAKE_C_COMPILER ${_mingw}-gcc-posix)
set(CMAKE_CXX_COMPILER ${_mingw}-g++-posix)
set(CMAKE_RC_COMPILER ${_mingw}-windres)
set(CMAKE_FIND_ROOT_PATH /usr/${_mingw})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
# One self-contained .exe: libstdc++, libgcc and winpthreads linked in, no DLLs to put beside it.
set(CMAKE_EXE_LINKER_FLAGS_INIT "-static")
# ctest (and anything CMake runs of the target's) goes through wine.
set(CMAKE_CROSSCOMPILING_EMULATOR /usr/lib/wine/wine64)
