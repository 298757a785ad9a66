# Script mode: fails the build when a source file includes a folder its layer
# may not see, or when a GPU stage (render/) could touch the file system.
# The table is docs/architecture.md's "who may include whom", one row per
# folder; a file obeys the row of the longest folder that holds it, and may
# always include its own folder. Includes are the quoted ones ("a/b.h").
# Each row: folder|prefixes it may include, separated by commas.
cmake_policy(SET CMP0007 NEW)
set(rules
  "bridge/core|"
  "bridge/grid|bridge/core/"
  "bridge/layout|"
  "bridge/mesh|bridge/core/"
  "bridge/scene|bridge/core/,bridge/grid/"
  "io/files|bridge/"
  "io/image|bridge/,io/files/"
  "io/mesh|bridge/,io/files/"
  "io/export|bridge/"
  "io/vtk|bridge/,io/files/,io/export/"
  "io/vdb|bridge/,io/files/,io/export/"
  "io/scene|bridge/,io/"
  "sim|bridge/,sim/"
  "sim/field|bridge/"
  "sim/fluid|bridge/,sim/field/,shaders/common/"
  "sim/optics|bridge/,sim/field/,shaders/common/"
  "sim/voxelize|bridge/,sim/optics/"
  "sim/deform|bridge/,io/mesh/"
  "sim/volume|bridge/,io/vdb/,io/vtk/,sim/optics/"
  "sim/gpu|bridge/,sim/field/,sim/fluid/,sim/deform/,gl/,shaders/common/"
  "gl|bridge/core/"
  "render/stages|bridge/,shaders/,gl/"
  "render/graph|bridge/,gl/,render/stages/"
  "shaders|common/,shaders/common/,bridge/layout/"
  "shaders/sim|common/,sim/,bridge/layout/"
  "verify/reference|bridge/"
  "verify/plot|bridge/,io/files/"
  "verify/converge|bridge/,sim/,render/,verify/plot/"
  "verify/accuracy|bridge/,io/files/,io/image/,render/,verify/reference/,verify/plot/"
  "apps/common|bridge/,io/,sim/,render/,gl/"
  "apps/eikon|bridge/,io/,sim/,render/,gl/,verify/,apps/common/"
  "apps/viewer|bridge/,render/,gl/"
  "apps/eikon-view|bridge/,io/,sim/,render/,gl/,apps/common/,apps/viewer/"
  "apps/library|eikon/,bridge/,io/,sim/,render/,gl/,apps/common/,apps/viewer/"
  "apps/python|eikon/"
  "include/eikon|"
)
# What a GPU stage must not use: it gets its inputs as data (docs/architecture.md).
set(file_system_patterns "#[ \t]*include[ \t]*<(fstream|filesystem)>" "fopen[ \t]*\\(" "std::[io]?fstream")

set(violations "")
file(GLOB_RECURSE sources
     ${ROOT}/bridge/* ${ROOT}/io/* ${ROOT}/sim/* ${ROOT}/render/* ${ROOT}/shaders/* ${ROOT}/verify/* ${ROOT}/apps/* ${ROOT}/include/*)
list(FILTER sources INCLUDE REGEX "\\.(h|cpp|glsl|comp)$")
foreach(source IN LISTS sources)
  file(RELATIVE_PATH rel ${ROOT} ${source})
  get_filename_component(folder ${rel} DIRECTORY)
  # The row of the longest folder holding this file.
  set(row_folder "")
  set(allowed "")
  foreach(rule IN LISTS rules)
    string(FIND "${rule}" "|" bar)
    string(SUBSTRING "${rule}" 0 ${bar} rule_folder)
    if((folder STREQUAL rule_folder OR folder MATCHES "^${rule_folder}/") AND NOT row_folder MATCHES "^${rule_folder}.+")
      string(LENGTH "${rule_folder}" new_length)
      string(LENGTH "${row_folder}" old_length)
      if(new_length GREATER old_length)
        set(row_folder ${rule_folder})
        string(FIND "${rule}" "|" bar)
        math(EXPR bar "${bar} + 1")
        string(SUBSTRING "${rule}" ${bar} -1 allowed)
        string(REPLACE "," ";" allowed "${allowed}")
      endif()
    endif()
  endforeach()
  if(row_folder STREQUAL "")
    list(APPEND violations "${rel}: its folder has no row in cmake/CheckLayering.cmake")
    continue()
  endif()
  list(APPEND allowed "${row_folder}/")
  file(STRINGS ${source} includes REGEX "^[ \t]*#[ \t]*include[ \t]*\"")
  foreach(line IN LISTS includes)
    string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]*\"([^\"]*)\".*" "\\1" target "${line}")
    if(NOT target MATCHES "/")
      continue()  # a file beside it
    endif()
    set(ok FALSE)
    foreach(prefix IN LISTS allowed)
      string(LENGTH "${prefix}" length)
      string(SUBSTRING "${target}" 0 ${length} head)
      if(head STREQUAL prefix)
        set(ok TRUE)
      endif()
    endforeach()
    if(NOT ok)
      list(APPEND violations "${rel}: includes \"${target}\", which ${row_folder}/ may not see")
    endif()
  endforeach()
  if(rel MATCHES "^render/")
    file(READ ${source} text)
    foreach(pattern IN LISTS file_system_patterns)
      if(text MATCHES "${pattern}")
        list(APPEND violations "${rel}: touches the file system (${CMAKE_MATCH_0}): a GPU stage gets its inputs as data")
      endif()
    endforeach()
  endif()
endforeach()
if(violations)
  list(JOIN violations "\n  " text)
  message(FATAL_ERROR "Layering violations (docs/architecture.md, cmake/CheckLayering.cmake):\n  ${text}")
endif()
