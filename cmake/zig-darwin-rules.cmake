# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
# Read by CMake after its Darwin rules when cmake/zig-toolchain.cmake builds
# for macOS: a module is linked as a dylib (-shared), not a bundle (-bundle,
# which zig's linker does not take).
set(CMAKE_SHARED_MODULE_CREATE_C_FLAGS "-shared")
set(CMAKE_SHARED_MODULE_CREATE_CXX_FLAGS "-shared")
