# SPDX-FileCopyrightText: Copyright (c) 2026 the NarrowVolume developers
# SPDX-License-Identifier: BSD-3-Clause
#
# Debian's ParaView 5.13 (Debian 13) cannot be found by find_package as
# installed: VTKPython-targets.cmake and ParaViewPython-targets.cmake name the
# Python extension modules as the build made them (vtkmodules/vtkCommonCore.so),
# but the package ships them under the name dh_python3 gives them afterwards
# (vtkmodules/vtkCommonCore.cpython-313-x86_64-linux-gnu.so; the packaging
# dropped --no-ext-rename in 5.13.2+dfsg-2), and the check at the end of each
# generated targets file stops the configuration on the first missing file.
#
# narrowvolume_repair_python_exports() runs before find_package. For each such
# export set whose named files are all missing but whose renamed files are all
# there, it writes a copy of the targets files into the build tree with the
# renamed files' names and includes it. The targets then exist with the
# properties the package meant; when find_package includes the installed file
# later, that file finds all its targets defined and returns at once (its guard
# against a second inclusion). Nothing of the installed packages is changed,
# and where the files are as named (Debian 12, other VTKs) nothing happens.
#
#   narrowvolume_repair_python_exports(PACKAGES <name>...)
# looks for the config folders of each package (<Name>_DIR when set, otherwise
# <prefix>/lib/<arch>/cmake/<name>-* and <prefix>/lib/cmake/<name>-* under the
# usual prefixes, and the vtk/ folder of a ParaView that bundles its VTK).
# List VTK before ParaView: ParaView's Python targets use VTK's.

function (_narrowvolume_config_dirs name out)
  string(TOLOWER "${name}" lower)
  if (${name}_DIR)
    set(dirs "${${name}_DIR}")
  else ()
    set(dirs)
    foreach (prefix IN LISTS CMAKE_PREFIX_PATH CMAKE_SYSTEM_PREFIX_PATH)
      file(GLOB found LIST_DIRECTORIES true
        "${prefix}/lib/${CMAKE_LIBRARY_ARCHITECTURE}/cmake/${lower}-*"
        "${prefix}/lib/cmake/${lower}-*")
      foreach (dir IN LISTS found)
        # / and /usr are one tree on merged-/usr systems.
        get_filename_component(dir "${dir}" REALPATH)
        list(APPEND dirs "${dir}")
      endforeach ()
    endforeach ()
    list(REMOVE_DUPLICATES dirs)
    list(LENGTH dirs count)
    if (count GREATER 1)
      # Which one find_package takes is its business: do not guess.
      message(STATUS "NarrowVolume: several ${name} installations (${dirs}); set ${name}_DIR "
        "if find_package(${name}) stops on missing Python modules")
      set(dirs)
    endif ()
  endif ()
  set(${out} ${dirs} PARENT_SCOPE)
endfunction ()

# Repairs one export set: <dir>/<set>-targets.cmake and its per-configuration
# files <dir>/<set>-targets-<config>.cmake.
function (_narrowvolume_repair_export_set main_file)
  get_filename_component(dir "${main_file}" DIRECTORY)
  get_filename_component(set_name "${main_file}" NAME_WE)
  file(GLOB config_files "${dir}/${set_name}-*.cmake")
  file(READ "${main_file}" main_text)
  # The file finds its prefix by going up from its own folder once per line.
  string(REGEX MATCHALL "get_filename_component\\(_IMPORT_PREFIX \"\\\${_IMPORT_PREFIX}\" PATH\\)"
    ups "${main_text}")
  set(prefix "${dir}")
  foreach (up IN LISTS ups)
    get_filename_component(prefix "${prefix}" DIRECTORY)
  endforeach ()

  set(renamed 0)
  set(copies)
  foreach (config_file IN LISTS config_files)
    file(READ "${config_file}" text)
    string(REGEX MATCHALL "\\\${_IMPORT_PREFIX}/[^\"]*\\.so\"" named "${text}")
    list(REMOVE_DUPLICATES named)
    foreach (entry IN LISTS named)
      string(REGEX REPLACE "^\\\${_IMPORT_PREFIX}/(.*)\"$" "\\1" relative "${entry}")
      if (EXISTS "${prefix}/${relative}")
        return () # the files are as named: nothing to repair
      endif ()
      # vtkmodules/vtkCommonCore.so -> vtkmodules/vtkCommonCore.<python tag>.so
      string(REGEX REPLACE "\\.so$" "" stem "${relative}")
      file(GLOB candidates RELATIVE "${prefix}" "${prefix}/${stem}.*.so")
      list(LENGTH candidates count)
      if (NOT count EQUAL 1)
        return () # another problem than the renaming: let find_package report it
      endif ()
      string(REPLACE "\${_IMPORT_PREFIX}/${relative}\"" "\${_IMPORT_PREFIX}/${candidates}\"" text "${text}")
      math(EXPR renamed "${renamed} + 1")
    endforeach ()
    list(APPEND copies "${config_file}")
    set("text_${config_file}" "${text}")
  endforeach ()
  if (renamed EQUAL 0)
    return ()
  endif ()

  string(MD5 key "${main_file}")
  set(copy_dir "${CMAKE_BINARY_DIR}/CMakeFiles/NarrowVolumePythonExports/${key}")
  file(REMOVE_RECURSE "${copy_dir}")
  foreach (config_file IN LISTS copies)
    get_filename_component(name "${config_file}" NAME)
    file(WRITE "${copy_dir}/${name}" "${text_${config_file}}")
  endforeach ()
  # The copy computes the prefix from the installed file's place, not its own.
  string(REPLACE "get_filename_component(_IMPORT_PREFIX \"\${CMAKE_CURRENT_LIST_FILE}\" PATH)"
    "get_filename_component(_IMPORT_PREFIX \"${main_file}\" PATH)" main_text "${main_text}")
  file(WRITE "${copy_dir}/${set_name}.cmake" "${main_text}")
  message(STATUS "NarrowVolume: ${main_file} names ${renamed} Python module files by their "
    "names before packaging; using a copy with their installed names (${copy_dir})")
  include("${copy_dir}/${set_name}.cmake")
endfunction ()

macro (narrowvolume_repair_python_exports)
  cmake_parse_arguments(_nv_repair "" "" "PACKAGES" ${ARGN})
  set(_nv_repair_dirs)
  foreach (_nv_repair_package IN LISTS _nv_repair_PACKAGES)
    _narrowvolume_config_dirs(${_nv_repair_package} _nv_repair_found)
    foreach (_nv_repair_dir IN LISTS _nv_repair_found)
      # A ParaView that bundles its VTK keeps VTK's config in its vtk/ folder.
      if (IS_DIRECTORY "${_nv_repair_dir}/vtk")
        list(APPEND _nv_repair_dirs "${_nv_repair_dir}/vtk")
      endif ()
      list(APPEND _nv_repair_dirs "${_nv_repair_dir}")
    endforeach ()
  endforeach ()
  list(REMOVE_DUPLICATES _nv_repair_dirs)
  foreach (_nv_repair_dir IN LISTS _nv_repair_dirs)
    file(GLOB _nv_repair_sets "${_nv_repair_dir}/*Python*-targets.cmake")
    foreach (_nv_repair_set IN LISTS _nv_repair_sets)
      # A macro, so that the imported targets land in the caller's directory.
      _narrowvolume_repair_export_set("${_nv_repair_set}")
    endforeach ()
  endforeach ()
endmacro ()
