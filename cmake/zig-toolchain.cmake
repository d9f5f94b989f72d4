# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
# Cross builds of the wheel's module with zig (scripts/build-wheels.sh):
# zig's clang compiles for another OS, processor or C library, with its own
# libc++ linked in statically, so one Linux machine makes every wheel.
#
# The environment says which target: NV_ZIG_TARGET, zig's target triple
# (x86_64-linux-gnu.2.17, aarch64-linux-gnu.2.17, x86_64-windows-gnu,
# x86_64-macos.10.15, aarch64-macos.11.0); NV_ZIG_TOOLS, a folder with the
# wrappers zig-cc, zig-c++, zig-ar and zig-ranlib that run
# `zig cc -target $NV_ZIG_TARGET` and so on (build-wheels.sh writes them).
set(_nv_target "$ENV{NV_ZIG_TARGET}")
set(_nv_tools "$ENV{NV_ZIG_TOOLS}")
if (NOT _nv_target OR NOT _nv_tools)
  message(FATAL_ERROR "cmake/zig-toolchain.cmake needs NV_ZIG_TARGET and NV_ZIG_TOOLS in the environment "
    "(scripts/build-wheels.sh sets them).")
endif ()

if (_nv_target MATCHES "-linux-")
  set(CMAKE_SYSTEM_NAME Linux)
elseif (_nv_target MATCHES "-windows-")
  set(CMAKE_SYSTEM_NAME Windows)
elseif (_nv_target MATCHES "-macos")
  set(CMAKE_SYSTEM_NAME Darwin)
  # zig's target carries the minimum macOS; CMake must add no -arch,
  # -isysroot or -mmacosx-version-min of its own.
  set(CMAKE_OSX_ARCHITECTURES "" CACHE STRING "" FORCE)
  set(CMAKE_OSX_SYSROOT "" CACHE PATH "" FORCE)
  set(CMAKE_OSX_DEPLOYMENT_TARGET "" CACHE STRING "" FORCE)
  # zig's Mach-O linker crashes on -bundle: a Python module is loaded the
  # same whether it is a bundle or a dylib.
  set(CMAKE_USER_MAKE_RULES_OVERRIDE "${CMAKE_CURRENT_LIST_DIR}/zig-darwin-rules.cmake")
else ()
  message(FATAL_ERROR "cmake/zig-toolchain.cmake: unknown target ${_nv_target}")
endif ()
string(REGEX MATCH "^[^-]+" CMAKE_SYSTEM_PROCESSOR "${_nv_target}")

set(CMAKE_C_COMPILER "${_nv_tools}/zig-cc")
set(CMAKE_CXX_COMPILER "${_nv_tools}/zig-c++")
set(CMAKE_AR "${_nv_tools}/zig-ar" CACHE FILEPATH "" FORCE)
set(CMAKE_RANLIB "${_nv_tools}/zig-ranlib" CACHE FILEPATH "" FORCE)

# Find the target Python's headers where they are given, programs on the
# building machine.
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
