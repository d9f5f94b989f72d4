# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
# The InstallConsumer test (cmake -P): installs the build into WORK_DIR/prefix
# and uses it as a stranger would.
#   1. cmake --install BUILD_DIR --prefix WORK_DIR/prefix; the config, version,
#      targets files are there and name no build or source path; the version
#      file accepts this major.minor and refuses the next one;
#   2. with the plugin: the plugin, the Python readers it loads
#      (python/NarrowVolumeScanReaders.py) and narrowvolume.plugins.xml sit under
#      LIBDIR/PLUGIN_SUBDIR, and ldd resolves libNarrowVolumeFilters and
#      libNarrowVolumeReaders of the installed plugin (and Python modules) to
#      the installed libraries;
#   3. configures the consumer project (this folder) with only
#      CMAKE_PREFIX_PATH=prefix (VTK_DIR, ParaView_DIR, CMAKE_PREFIX_PATH
#      removed from the environment: the config's own VTK hint must work),
#      builds it and runs it (a PCD file through the installed reader, then
#      the installed filter);
#   4. with the plugin: pvpython with PV_PLUGIN_CONFIG_FILE=<installed xml>
#      autoloads the installed plugin (check_installed_plugin.py).
# Variables (-D): BUILD_DIR SOURCE_DIR WORK_DIR GENERATOR CXX_COMPILER
# BUILD_TYPE VERSION VTK_DIR LIBDIR CMAKE_DESTINATION WITH_PLUGIN PLUGIN_SUBDIR
# PVPYTHON WITH_PYTHON PYTHON_DESTINATION.
cmake_minimum_required(VERSION 3.16)

set(failures 0)
macro (fail what)
  message("FAILED: ${what}")
  math(EXPR failures "${failures} + 1")
endmacro ()

# run(<step> <command>...): runs a command, shows its output only when it
# fails; step_ok tells whether it succeeded.
set(timings "")
function (run step)
  string(TIMESTAMP start "%s")
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE out)
  string(TIMESTAMP end "%s")
  math(EXPR took "${end} - ${start}")
  set(timings ${timings} "${step} ${took} s" PARENT_SCOPE)
  set(step_output "${out}" PARENT_SCOPE)
  if (result EQUAL 0)
    set(step_ok TRUE PARENT_SCOPE)
  else ()
    set(step_ok FALSE PARENT_SCOPE)
    message("${out}")
    message("FAILED: ${step} (exit ${result}): ${ARGN}")
  endif ()
endfunction ()

macro (finish)
  list(JOIN timings ", " timings)
  if (failures GREATER 0)
    message(FATAL_ERROR "InstallConsumer: ${failures} failed checks (${timings})")
  endif ()
  message("InstallConsumer: passed (${timings})")
  return ()
endmacro ()

set(prefix "${WORK_DIR}/prefix")
set(consumer_build "${WORK_DIR}/consumer-build")
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")

# --- 1. Install.
run(install "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${prefix}")
if (NOT step_ok)
  math(EXPR failures "${failures} + 1")
  finish()
endif ()
set(cmake_dir "${prefix}/${CMAKE_DESTINATION}")
foreach (name NarrowVolumeConfig NarrowVolumeConfigVersion NarrowVolume-targets NarrowVolume-vtk-module-properties)
  if (NOT EXISTS "${cmake_dir}/${name}.cmake")
    fail("${cmake_dir}/${name}.cmake is not installed")
  endif ()
endforeach ()
get_filename_component(source_root "${SOURCE_DIR}/../.." ABSOLUTE)
file(GLOB cmake_files "${cmake_dir}/*.cmake")
foreach (file IN LISTS cmake_files)
  file(READ "${file}" text)
  foreach (tree "${BUILD_DIR}" "${source_root}")
    string(FIND "${text}" "${tree}" at)
    if (at GREATER -1)
      fail("${file} names ${tree}: the installed tree is not relocatable")
    endif ()
  endforeach ()
endforeach ()

# The version file: SameMinorVersion.
string(REGEX MATCH "^([0-9]+)\\.([0-9]+)" _ "${VERSION}")
set(major "${CMAKE_MATCH_1}")
set(minor "${CMAKE_MATCH_2}")
math(EXPR next_minor "${minor} + 1")
foreach (wanted "${major}.${minor}:TRUE" "${major}.${next_minor}:FALSE")
  string(REPLACE ":" ";" wanted "${wanted}")
  list(GET wanted 0 PACKAGE_FIND_VERSION)
  list(GET wanted 1 expected)
  string(REPLACE "." ";" parts "${PACKAGE_FIND_VERSION}")
  list(GET parts 0 PACKAGE_FIND_VERSION_MAJOR)
  list(GET parts 1 PACKAGE_FIND_VERSION_MINOR)
  set(PACKAGE_FIND_VERSION_PATCH 0)
  set(PACKAGE_FIND_VERSION_COUNT 2)
  set(CMAKE_SIZEOF_VOID_P 8)
  unset(PACKAGE_VERSION_COMPATIBLE)
  include("${cmake_dir}/NarrowVolumeConfigVersion.cmake" OPTIONAL)
  if (NOT PACKAGE_VERSION_COMPATIBLE STREQUAL expected)
    fail("NarrowVolume ${VERSION} compatible with a request for ${PACKAGE_FIND_VERSION}: "
      "'${PACKAGE_VERSION_COMPATIBLE}', expected ${expected}")
  endif ()
endforeach ()

# --- 2. The plugin, its XML and the run-time paths of the installed libraries.
set(plugin "${prefix}/${LIBDIR}/${PLUGIN_SUBDIR}/NarrowVolume/NarrowVolume.so")
set(plugins_xml "${prefix}/${LIBDIR}/${PLUGIN_SUBDIR}/narrowvolume.plugins.xml")
set(library_dir "${prefix}/${LIBDIR}")
set(installed_binaries "")
if (WITH_PLUGIN)
  if (NOT EXISTS "${plugin}")
    fail("the plugin is not installed at ${plugin}")
  else ()
    list(APPEND installed_binaries "${plugin}")
  endif ()
  if (NOT EXISTS "${prefix}/${LIBDIR}/${PLUGIN_SUBDIR}/NarrowVolume/python/NarrowVolumeScanReaders.py")
    fail("the Python readers are not installed in python/ below the plugin")
  endif ()
  if (NOT EXISTS "${plugins_xml}")
    fail("the plugins XML is not installed at ${plugins_xml}")
  else ()
    file(READ "${plugins_xml}" xml)
    # ParaView 5.13 adds delayed_load="0" (paraview_plugin_build's DELAYED_LOAD),
    # ParaView 6 the plugin's version and description.
    if (NOT xml MATCHES "<Plugin name=\"NarrowVolume\" auto_load=\"1\"( delayed_load=\"0\")?( [a-z_]+=\"[^\"]*\")*/>")
      fail("${plugins_xml} does not list NarrowVolume for auto-loading:\n${xml}")
    endif ()
  endif ()
endif ()
if (WITH_PYTHON)
  set(python_dir "${prefix}/${PYTHON_DESTINATION}")
  file(GLOB python_module "${python_dir}/narrowvolume/NarrowVolumeFilters*.so"
    "${python_dir}/narrowvolume/NarrowVolumeReaders*.so")
  list(LENGTH python_module python_modules)
  if (NOT python_modules EQUAL 2 OR NOT EXISTS "${python_dir}/narrowvolume/__init__.py")
    fail("the narrowvolume package is not installed in ${python_dir}")
  endif ()
  list(APPEND installed_binaries ${python_module})
endif ()

# ldd: each of our libraries the binary needs (libNarrowVolumeFilters,
# libNarrowVolumeReaders; at least one) found, and in the prefix (the RPATH's
# $ORIGIN).
function (check_libraries binary)
  execute_process(COMMAND "${LDD}" "${binary}" RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE out)
  set(checked 0)
  foreach (library IN ITEMS libNarrowVolumeFilters libNarrowVolumeReaders)
    if (NOT out MATCHES "${library}")
      continue ()
    endif ()
    math(EXPR checked "${checked} + 1")
    string(REGEX MATCH "${library}[^ ]* => ([^ ]*)" _ "${out}")
    set(found "${CMAKE_MATCH_1}")
    set(found_dir "")
    if (found)
      get_filename_component(found "${found}" REALPATH)
      get_filename_component(expected_dir "${library_dir}" REALPATH)
      get_filename_component(found_dir "${found}" DIRECTORY)
    endif ()
    if (NOT result EQUAL 0 OR NOT found OR NOT found_dir STREQUAL expected_dir)
      message("${out}")
      fail("${binary}: ${library} resolves to '${found}', not to ${library_dir}")
    endif ()
  endforeach ()
  if (checked EQUAL 0 OR out MATCHES "not found")
    message("${out}")
    fail("${binary}: none of our libraries, or one not found")
  endif ()
  set(failures "${failures}" PARENT_SCOPE)
endfunction ()
find_program(LDD ldd)
if (LDD)
  foreach (binary IN LISTS installed_binaries)
    check_libraries("${binary}")
  endforeach ()
else ()
  message("InstallConsumer: no ldd, run-time paths not checked")
endif ()

# --- 3. The consumer project: configure with only CMAKE_PREFIX_PATH, build, run.
set(clean_env "${CMAKE_COMMAND}" -E env --unset=VTK_DIR --unset=ParaView_DIR --unset=NarrowVolume_DIR
  --unset=CMAKE_PREFIX_PATH)
run(configure ${clean_env} "${CMAKE_COMMAND}" -S "${SOURCE_DIR}" -B "${consumer_build}" -G "${GENERATOR}"
  "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}" "-DCMAKE_BUILD_TYPE=${BUILD_TYPE}"
  "-DCMAKE_PREFIX_PATH=${prefix}" "-DNARROWVOLUME_VERSION_WANTED=${major}.${minor}")
if (NOT step_ok)
  math(EXPR failures "${failures} + 1")
  finish()
endif ()
set(configure_output "${step_output}")
# It found the installed NarrowVolume, the VTK it was built with, and the paths.
macro (expect_status label expected)
  if (configure_output MATCHES "-- ${label}: ([^\n]*)")
    set(got "${CMAKE_MATCH_1}")
    get_filename_component(got_real "${got}" REALPATH)
    get_filename_component(expected_real "${expected}" REALPATH)
    if (NOT got_real STREQUAL expected_real)
      fail("the consumer's ${label} is ${got}, expected ${expected}")
    endif ()
  else ()
    fail("the consumer printed no '${label}:'")
  endif ()
endmacro ()
if (configure_output MATCHES "-- NarrowVolume ([^ ]*) from ([^\n]*)")
  set(found_version "${CMAKE_MATCH_1}")
  get_filename_component(found_dir "${CMAKE_MATCH_2}" REALPATH)
  get_filename_component(expected_dir "${cmake_dir}" REALPATH)
  if (NOT found_version STREQUAL VERSION OR NOT found_dir STREQUAL expected_dir)
    fail("the consumer found NarrowVolume ${found_version} in ${found_dir}, expected ${VERSION} in ${expected_dir}")
  endif ()
else ()
  fail("the consumer did not report NarrowVolume")
endif ()
if (configure_output MATCHES "-- VTK [^ ]* from ([^\n]*)")
  get_filename_component(found_vtk "${CMAKE_MATCH_1}" REALPATH)
  get_filename_component(expected_vtk "${VTK_DIR}" REALPATH)
  if (NOT found_vtk STREQUAL expected_vtk)
    fail("the consumer found VTK in ${found_vtk}, not the build's ${expected_vtk}")
  endif ()
else ()
  fail("the consumer did not report VTK")
endif ()
if (WITH_PLUGIN)
  expect_status("ParaView plugin" "${plugin}")
  expect_status("ParaView plugins file" "${plugins_xml}")
  expect_status("NarrowVolume::Plugins plugins file" "${plugins_xml}")
endif ()

run(build "${CMAKE_COMMAND}" --build "${consumer_build}" --parallel 2)
if (NOT step_ok)
  math(EXPR failures "${failures} + 1")
  finish()
endif ()
file(GLOB consumer "${consumer_build}/nv_consumer" "${consumer_build}/*/nv_consumer")
if (LDD AND consumer)
  check_libraries("${consumer}")
endif ()
run(run ${clean_env} "${consumer_build}/nv_consumer" "${consumer_build}")
if (NOT step_ok OR NOT step_output MATCHES "nv_consumer: .*: ok")
  if (step_ok)
    message("${step_output}")
  endif ()
  fail("the consumer program")
else ()
  string(STRIP "${step_output}" step_output)
  message("${step_output}")
endif ()

# --- 4. ParaView autoloads the installed plugin from its XML.
if (WITH_PLUGIN)
  set(pvpython_args "${prefix}")
  set(pythonpath "")
  if (WITH_PYTHON)
    set(pythonpath "PYTHONPATH=${prefix}/${PYTHON_DESTINATION}")
    list(APPEND pvpython_args "${prefix}/${PYTHON_DESTINATION}")
  endif ()
  run(pvpython "${CMAKE_COMMAND}" -E env --unset=PV_PLUGIN_PATH --unset=PYTHONPATH
    "PV_PLUGIN_CONFIG_FILE=${plugins_xml}" ${pythonpath}
    "${PVPYTHON}" --force-offscreen-rendering "${SOURCE_DIR}/check_installed_plugin.py" ${pvpython_args})
  if (step_ok)
    string(STRIP "${step_output}" step_output)
    message("${step_output}")
  else ()
    math(EXPR failures "${failures} + 1")
  endif ()
endif ()

finish()
