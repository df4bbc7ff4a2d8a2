# A damaged packing-cache entry is not used: a run with a grain of the cached column moved gives
# the same timeseries.csv as the run that made the entry, and the entry is written again whole.
# Usage: cmake -DLBDEM=... -DCASE=default.toml -DOUT=... -P this.
file(REMOVE_RECURSE "${OUT}")
set(cache "${OUT}/cache")
set(small --set grains.count=150 --set grains.packing=0.79 --set fluid.enabled=false
    --set run.end_tc=0.5 --set run.output_interval_tc=0.25 --set output.vtk=false)

# Runs the small case into OUT/dir with the test's own cache; fails on a non-zero exit.
function(run_with_cache dir)
    execute_process(COMMAND "${CMAKE_COMMAND}" -E env "LBDEM_CACHE_DIR=${cache}"
                            "${LBDEM}" run "${CASE}" ${small} --out "${OUT}/${dir}" --quiet
                    RESULT_VARIABLE code ERROR_VARIABLE err)
    if(NOT code EQUAL 0)
        message(FATAL_ERROR "the run into ${dir} failed (${code}): ${err}")
    endif()
endfunction()

run_with_cache(made)
file(GLOB entries "${cache}/packing-*.txt")
list(LENGTH entries count)
if(NOT count EQUAL 1)
    message(FATAL_ERROR "expected one packing-cache entry, found ${count}: ${entries}")
endif()
file(READ "${entries}" intact)
# Swap the first grain's x and y (line 9: the header, seven column values, then x y r per grain).
file(STRINGS "${entries}" lines)
list(GET lines 8 grain)
string(REPLACE " " ";" fields "${grain}")
list(GET fields 0 x)
list(GET fields 1 y)
list(GET fields 2 r)
string(REPLACE "${grain}\n" "${y} ${x} ${r}\n" damaged "${intact}")
if(damaged STREQUAL intact)
    message(FATAL_ERROR "the test could not damage ${entries}")
endif()
file(WRITE "${entries}" "${damaged}")
run_with_cache(after_damage)
file(READ "${OUT}/made/timeseries.csv" made)
file(READ "${OUT}/after_damage/timeseries.csv" after)
if(NOT made STREQUAL after)
    message(FATAL_ERROR "a run after the cache entry was damaged differs from the run that made it:\n"
                        "${made}\n---\n${after}")
endif()
file(READ "${entries}" rewritten)
if(NOT rewritten STREQUAL intact)
    message(FATAL_ERROR "the damaged cache entry was not written again whole")
endif()
message(STATUS "ok: a damaged packing-cache entry is made again, and the run is the same")
