# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
# The version is set once, in CMakeLists.txt's project() (pyproject.toml,
# the package's __version__ and the docs read it there). CITATION.cff must
# write it itself: this checks that it agrees.
#   cmake -DVERSION=0.1.0 -DSOURCE_DIR=... -P check_version.cmake
file(STRINGS "${SOURCE_DIR}/CITATION.cff" citation REGEX "^version:")
string(REGEX REPLACE "^version: *\"?([^\"]*)\"? *$" "\\1" citation "${citation}")
if (NOT citation STREQUAL VERSION)
  message(FATAL_ERROR "CITATION.cff says version ${citation}, CMakeLists.txt's project() ${VERSION}: "
    "write the same in both.")
endif ()
message(STATUS "CITATION.cff and project() agree: ${VERSION}")
