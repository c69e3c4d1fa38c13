# Runs `vct bench --comparison` (one measured frame each) and checks comparison.json: the
# 1280×720 side-by-side setting timed with the camera moving and with the sun moving, and its
# error against cornell-sun's references at their size, all finite numbers (the JSON writes
# non-finite numbers as null).
#   cmake -DVCT=path/to/vct -DOUT_DIR=dir -P check_bench_comparison.cmake
cmake_minimum_required(VERSION 3.22)
file(REMOVE_RECURSE ${OUT_DIR})
execute_process(COMMAND ${VCT} bench --comparison --validate --frames 1 --warmup 0 --out-dir ${OUT_DIR}
                RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "vct bench --comparison failed (${result})")
endif()
if(NOT EXISTS ${OUT_DIR}/comparison.json)
  message(FATAL_ERROR "vct bench --comparison did not write comparison.json")
endif()
if(EXISTS ${OUT_DIR}/bench.json)
  message(FATAL_ERROR "vct bench --comparison also ran the matrix")
endif()
file(READ ${OUT_DIR}/comparison.json json)

function(expect_number)
  string(JSON type ERROR_VARIABLE json_error TYPE "${json}" ${ARGN})
  if(json_error OR NOT type STREQUAL "NUMBER")
    message(FATAL_ERROR "comparison.json: ${ARGN} is not a finite number (${type}${json_error})")
  endif()
endfunction()

foreach(key width height)
  expect_number(${key})
endforeach()
foreach(motion camera_moving sun_moving)
  expect_number(${motion} gpu_ms)
  expect_number(${motion} passes_ms shade)
endforeach()
expect_number(sun_moving passes_ms inject)
foreach(mode full direct indirect)
  expect_number(error ${mode} relmse)
  expect_number(error ${mode} luminance_ratio)
endforeach()
