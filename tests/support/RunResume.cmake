# `lbdem run --until-tc` then `lbdem resume`: the resumed run finishes, timeseries.csv holds each
# output time once and profiles/ one outline per output, numbered on across the resume; a short
# submerged run also writes the failure-plane pore pressure. Usage: cmake -DLBDEM=... -DCASE=...
# -DOUT=... -P this.
file(REMOVE_RECURSE "${OUT}" "${OUT}_wet" "${OUT}_whole")

# Fails unless FILE starts with HEADER and has at least MIN_ROWS further lines, each matching ROW.
function(expect_csv file header min_rows row)
    if(NOT EXISTS "${file}")
        message(FATAL_ERROR "missing ${file}")
    endif()
    file(STRINGS "${file}" lines)
    list(POP_FRONT lines first)
    if(NOT first STREQUAL header)
        message(FATAL_ERROR "${file}: header '${first}', expected '${header}'")
    endif()
    list(LENGTH lines count)
    if(count LESS min_rows)
        message(FATAL_ERROR "${file}: ${count} rows, expected at least ${min_rows}")
    endif()
    foreach(line IN LISTS lines)
        if(NOT line MATCHES "${row}")
            message(FATAL_ERROR "${file}: implausible row '${line}'")
        endif()
    endforeach()
endfunction()
# A length in metres within the 0.2 m x 0.1 m domain (non-negative, below 1), as %.7g/%.9g writes it.
set(metre "(0|0\\.[0-9]+|[1-9](\\.[0-9]+)?e-0[0-9])")
set(small --set grains.count=150 --set grains.packing=0.79 --set fluid.enabled=false
    --set run.end_tc=1 --set run.output_interval_tc=0.25)
execute_process(COMMAND "${LBDEM}" run "${CASE}" --out "${OUT}" --until-tc 0.5 --quiet ${small}
                RESULT_VARIABLE code ERROR_VARIABLE err)
if(NOT code EQUAL 0)
    message(FATAL_ERROR "run failed (${code}): ${err}")
endif()
file(READ "${OUT}/summary.json" summary)
if(NOT summary MATCHES "\"finished\": false")
    message(FATAL_ERROR "a run stopped at 0.5 tau_c must not be finished: ${summary}")
endif()
execute_process(COMMAND "${LBDEM}" resume "${OUT}" --quiet RESULT_VARIABLE code ERROR_VARIABLE err)
if(NOT code EQUAL 0)
    message(FATAL_ERROR "resume failed (${code}): ${err}")
endif()
file(READ "${OUT}/summary.json" summary)
if(NOT summary MATCHES "\"finished\": true")
    message(FATAL_ERROR "the resumed run did not finish: ${summary}")
endif()
# Resuming a finished run, to its end or to an earlier time, runs nothing and rewrites nothing.
foreach(until "" "--until-tc;0.5")
    execute_process(COMMAND "${LBDEM}" resume "${OUT}" ${until} --quiet RESULT_VARIABLE code ERROR_VARIABLE err)
    file(READ "${OUT}/summary.json" summaryAgain)
    if(NOT code EQUAL 0 OR NOT summaryAgain STREQUAL summary)
        message(FATAL_ERROR "resuming a finished run (${until}) must leave summary.json as it was (${code}): ${err}")
    endif()
endforeach()
file(STRINGS "${OUT}/timeseries.csv" rows)
list(LENGTH rows count)
if(NOT count EQUAL 6) # header + t/tc = 0, 0.25, 0.5, 0.75, 1
    message(FATAL_ERROR "expected 6 lines in timeseries.csv, got ${count}:\n${rows}")
endif()
# The same run without the stop writes the same timeseries.csv byte for byte, the five-output
# mean of the base stress included (a resumed run seeds it from the rows already written).
file(REMOVE_RECURSE "${OUT}_whole")
execute_process(COMMAND "${LBDEM}" run "${CASE}" --out "${OUT}_whole" --quiet ${small}
                RESULT_VARIABLE code ERROR_VARIABLE err)
if(NOT code EQUAL 0)
    message(FATAL_ERROR "uninterrupted run failed (${code}): ${err}")
endif()
file(READ "${OUT}/timeseries.csv" resumedSeries)
file(READ "${OUT}_whole/timeseries.csv" wholeSeries)
if(NOT resumedSeries STREQUAL wholeSeries)
    message(FATAL_ERROR "stopped and resumed, timeseries.csv differs from the uninterrupted run:\n"
                        "${resumedSeries}\n---\n${wholeSeries}")
endif()
if(NOT resumedSeries MATCHES "base_normal_stress_front_avg5_pa")
    message(FATAL_ERROR "timeseries.csv lacks base_normal_stress_front_avg5_pa")
endif()
foreach(index 000000 000001 000002 000003 000004)
    expect_csv("${OUT}/profiles/outline_${index}.csv" "x_m,y_m" 4 "^${metre},${metre}$")
endforeach()
if(EXISTS "${OUT}/profiles/outline_000005.csv" OR EXISTS "${OUT}/profiles/pore_pressure_failure_plane_000000.csv")
    message(FATAL_ERROR "a dry run to 1 tau_c writes outlines 0 to 4 and no pore pressure")
endif()

# Submerged, coarse and short: the pore pressure along the failure plane at each output.
execute_process(COMMAND "${LBDEM}" run "${CASE}" --out "${OUT}_wet" --quiet --set grains.count=150
                        --set grains.packing=0.79 --set fluid.resolution=4 --set run.end_tc=0.25
                        --set run.output_interval_tc=0.25 --set output.vtk=false
                RESULT_VARIABLE code ERROR_VARIABLE err)
if(NOT code EQUAL 0)
    message(FATAL_ERROR "submerged run failed (${code}): ${err}")
endif()
foreach(index 000000 000001)
    expect_csv("${OUT}_wet/profiles/outline_${index}.csv" "x_m,y_m" 4 "^${metre},${metre}$")
    # 64 probe points; the pressure (empty inside a grain) below 10 kPa in magnitude.
    set(pressure "(-?[0-9][0-9]?[0-9]?[0-9]?(\\.[0-9]+)?(e-[0-9]+)?)?")
    expect_csv("${OUT}_wet/profiles/pore_pressure_failure_plane_${index}.csv"
               "s_m,x_m,y_m,excess_pore_pressure_pa" 64 "^${metre},${metre},${metre},${pressure}$")
endforeach()
file(STRINGS "${OUT}_wet/profiles/pore_pressure_failure_plane_000001.csv" rows REGEX ",-?[0-9][^,]*$")
list(LENGTH rows fluidPoints)
if(fluidPoints LESS 8)
    message(FATAL_ERROR "only ${fluidPoints} of 64 failure-plane points carry a pressure after 0.25 tau_c")
endif()
message(STATUS "ok: run to 0.5 tau_c, resumed to 1 tau_c, ${count} lines, outlines 0-4; "
               "submerged: ${fluidPoints} of 64 failure-plane points in the fluid")
