# Runs `vct bench --quick` on the Cornell box and checks that the CSV, JSON and SVG it writes exist,
# parse, and hold finite numbers (the JSON writes non-finite numbers as null, the CSV as "").
#   cmake -DVCT=path/to/vct -DOUT_DIR=dir -P check_bench_quick.cmake
cmake_minimum_required(VERSION 3.22)  # CMP0007: lists keep the CSV's empty fields
file(REMOVE_RECURSE ${OUT_DIR})
execute_process(COMMAND ${VCT} bench --quick --validate --scenes cornell --frames 2 --out-dir ${OUT_DIR}
                RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "vct bench --quick failed (${result})")
endif()
foreach(name bench.csv bench.json bench.svg)
  if(NOT EXISTS ${OUT_DIR}/${name})
    message(FATAL_ERROR "vct bench did not write ${name}")
  endif()
endforeach()

# JSON: every result has finite times, memory and errors for full, direct and indirect light, and
# for indirect light in the Cornell box's shadows.
file(READ ${OUT_DIR}/bench.json json)
string(JSON results ERROR_VARIABLE json_error GET "${json}" results)
if(json_error)
  message(FATAL_ERROR "bench.json does not parse: ${json_error}")
endif()
string(JSON count LENGTH "${json}" results)
if(NOT count EQUAL 2)
  message(FATAL_ERROR "bench.json has ${count} results, expected 2 (the quick matrix on one scene)")
endif()
math(EXPR last "${count} - 1")
foreach(i RANGE ${last})
  foreach(path "static;gpu_ms" "light_change;gpu_ms" "device_memory_bytes"
               "error;full;relmse" "error;full;rmse" "error;full;luminance_ratio" "error;full;share_off"
               "error;direct;relmse" "error;direct;luminance_ratio" "error;indirect;relmse"
               "error;indirect;luminance_ratio" "error;indirect;share_off"
               "error;shadowed_indirect_luminance_ratio")
    string(JSON type TYPE "${json}" results ${i} ${path})
    if(NOT type STREQUAL "NUMBER")
      message(FATAL_ERROR "bench.json results[${i}].${path} is ${type}, not a finite number")
    endif()
  endforeach()
  string(JSON finite GET "${json}" results ${i} finite)
  if(NOT finite)
    message(FATAL_ERROR "bench.json results[${i}] has non-finite pixels")
  endif()
endforeach()
string(JSON summary_count LENGTH "${json}" summary)
if(NOT summary_count EQUAL 2)
  message(FATAL_ERROR "bench.json has ${summary_count} summary rows, expected 2")
endif()
foreach(i 0 1)
  string(JSON type TYPE "${json}" summary ${i} shadowed_luminance_ratio_indirect)
  if(NOT type STREQUAL "NUMBER")
    message(FATAL_ERROR "bench.json summary[${i}].shadowed_luminance_ratio_indirect is ${type}, not a finite number")
  endif()
endforeach()

# CSV: a header and two rows with as many fields, the numeric ones all finite.
file(STRINGS ${OUT_DIR}/bench.csv lines)
list(LENGTH lines line_count)
if(NOT line_count EQUAL 3)
  message(FATAL_ERROR "bench.csv has ${line_count} lines, expected a header and 2 rows")
endif()
list(GET lines 0 header)
string(REPLACE "," ";" header_fields "${header}")
list(LENGTH header_fields field_count)
foreach(row 1 2)
  list(GET lines ${row} line)
  string(REPLACE "," ";" fields "${line}")
  list(LENGTH fields row_count)
  if(NOT row_count EQUAL field_count)
    message(FATAL_ERROR "bench.csv row ${row} has ${row_count} fields, the header ${field_count}")
  endif()
  foreach(column static_gpu_ms light_change_gpu_ms device_mb full_relmse direct_relmse indirect_relmse
                 indirect_luminance_ratio indirect_share_off shadowed_indirect_luminance_ratio)
    list(FIND header_fields ${column} at)
    list(GET fields ${at} value)
    if(at LESS 0 OR NOT value MATCHES "^[0-9.eE+-]+$" OR value MATCHES "[nN][aA][nN]|[iI][nN][fF]")
      message(FATAL_ERROR "bench.csv row ${row}: ${column} is '${value}', not a finite number")
    endif()
  endforeach()
endforeach()

# SVG: a whole document with the points and the Pareto front.
file(READ ${OUT_DIR}/bench.svg svg)
if(NOT svg MATCHES "^<svg " OR NOT svg MATCHES "</svg>\n$" OR NOT svg MATCHES "<polyline" OR NOT svg MATCHES "<circle")
  message(FATAL_ERROR "bench.svg is not a complete plot with points and a front")
endif()
# The key's labels ("v32 c1 a60 s1 ...") are explained in the plot itself.
foreach(part "v64 = 64³ voxels" "c6 = 6 diffuse cones" "a40 = 40° cone aperture" "bconv / b1" "d4 = diffuse cones")
  string(FIND "${svg}" "${part}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "bench.svg does not explain its labels: no '${part}'")
  endif()
endforeach()
message(STATUS "vct bench --quick: CSV, JSON and SVG complete and finite")
