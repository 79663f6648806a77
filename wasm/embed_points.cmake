# cmake -DOUTPUT=data.js -DNAMES="head;car" -DFILES="head.csv;car.csv" -P embed_points.cmake
# Writes the point sets of examples/ (the seeds' data) as one classic script,
# window.PlaygroundData = {head: [x0, y0, x1, y1, ...], ...}, so that the
# playground shows the very points the CLI reads, also from file://.
# A CSV here: '#' comment lines, one header line, then x,y rows.
set(script "// Generated from examples/*.csv by wasm/embed_points.cmake: do not edit.\n'use strict';\nwindow.PlaygroundData = {\n")
foreach(name file IN ZIP_LISTS NAMES FILES)
  file(STRINGS "${file}" lines)
  set(numbers)
  set(seen_header FALSE)
  foreach(line IN LISTS lines)
    if(line MATCHES "^#" OR line STREQUAL "")
      continue()
    endif()
    if(NOT seen_header)
      set(seen_header TRUE)
      continue()
    endif()
    string(REPLACE " " "" line "${line}")
    list(APPEND numbers "${line}")
  endforeach()
  list(JOIN numbers ", " joined)
  string(APPEND script "  ${name}: [${joined}],\n")
endforeach()
string(APPEND script "};\n")
file(WRITE "${OUTPUT}" "${script}")
