# `lbdem run --until-tc` then `lbdem resume`, once as after a kill (outputs written past the last
# checkpoint): the resumed run finishes with the same timeseries.csv, summary.json (but for its
# wall-time fields) and VTK series as an uninterrupted run, each output time once, profiles/ one
# outline per output; a short submerged run also writes the failure-plane pore pressure. Usage: cmake -DLBDEM=... -DCASE=...
# -DOUT=... -P this.
file(REMOVE_RECURSE "${OUT}" "${OUT}_wet" "${OUT}_whole" "${OUT}_checkpoint_at_1_75.h5")

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
# Dry, on a flat floor: the kinetic energy peaks at 1.75 tau_c (0.066 E_p0; 0.060 at 2).
set(small --set grains.count=150 --set grains.packing=0.79 --set fluid.enabled=false --set domain.slope_deg=0
    --set run.end_tc=2 --set run.output_interval_tc=0.25 --set output.checkpoint_interval_tc=0.5)

# Runs lbdem with ARGN and fails on a non-zero exit.
function(lbdem_ok what)
    execute_process(COMMAND "${LBDEM}" ${ARGN} RESULT_VARIABLE code ERROR_VARIABLE err)
    if(NOT code EQUAL 0)
        message(FATAL_ERROR "${what} failed (${code}): ${err}")
    endif()
endfunction()

# summary.json without the fields that depend on the machine (wall_s, mlups, stage_seconds).
function(summary_without_wall_time dir result)
    file(READ "${dir}/summary.json" json)
    foreach(field wall_s mlups stage_seconds)
        string(JSON json REMOVE "${json}" ${field})
    endforeach()
    set(${result} "${json}" PARENT_SCOPE)
endfunction()

# A run killed after its kinetic-energy peak: it stops at the peak, 1.75 tau_c (checkpoint), goes
# on to its end at 2 tau_c (output written), then its checkpoint goes back to the one at 1.75
# tau_c (as if killed at 2 just before its last checkpoint), and it is resumed to the end.
lbdem_ok("run to 1.75 tau_c" run "${CASE}" --out "${OUT}" --until-tc 1.75 --quiet ${small})
file(READ "${OUT}/summary.json" summary)
if(NOT summary MATCHES "\"finished\": false")
    message(FATAL_ERROR "a run stopped at 1.75 tau_c must not be finished: ${summary}")
endif()
file(COPY_FILE "${OUT}/checkpoint.h5" "${OUT}_checkpoint_at_1_75.h5")
lbdem_ok("resume to 2 tau_c" resume "${OUT}" --quiet)
file(COPY_FILE "${OUT}_checkpoint_at_1_75.h5" "${OUT}/checkpoint.h5")
file(WRITE "${OUT}/checkpoint.h5.tmp.999999" "left by a killed writer")
lbdem_ok("resume to the end" resume "${OUT}" --quiet)
if(EXISTS "${OUT}/checkpoint.h5.tmp.999999")
    message(FATAL_ERROR "a stale checkpoint.h5.tmp.* must be removed when the run continues")
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
if(NOT count EQUAL 10) # header + t/tc = 0, 0.25, ..., 2
    message(FATAL_ERROR "expected 10 lines in timeseries.csv, got ${count}:\n${rows}")
endif()
# The same run without the stops writes the same timeseries.csv byte for byte (the five-output
# mean of the base stress included), the same summary.json but for its wall-time fields (the
# kinetic-energy peak before the resume point included), and the same VTK series.
lbdem_ok("uninterrupted run" run "${CASE}" --out "${OUT}_whole" --quiet ${small})
file(READ "${OUT}/timeseries.csv" resumedSeries)
file(READ "${OUT}_whole/timeseries.csv" wholeSeries)
if(NOT resumedSeries STREQUAL wholeSeries)
    message(FATAL_ERROR "stopped and resumed, timeseries.csv differs from the uninterrupted run:\n"
                        "${resumedSeries}\n---\n${wholeSeries}")
endif()
if(NOT resumedSeries MATCHES "base_normal_stress_front_avg5_pa")
    message(FATAL_ERROR "timeseries.csv lacks base_normal_stress_front_avg5_pa")
endif()
summary_without_wall_time("${OUT}" resumedSummary)
summary_without_wall_time("${OUT}_whole" wholeSummary)
if(NOT resumedSummary STREQUAL wholeSummary)
    message(FATAL_ERROR "stopped and resumed, summary.json differs from the uninterrupted run:\n"
                        "${resumedSummary}\n---\n${wholeSummary}")
endif()
string(JSON peakTime GET "${wholeSummary}" t_ke_peak_over_tc)
if(peakTime GREATER 1.8)
    message(FATAL_ERROR "the kinetic-energy peak (t/tc = ${peakTime}) must come before the resume point")
endif()
file(GLOB series RELATIVE "${OUT}_whole/vtk" "${OUT}_whole/vtk/*.pvd")
file(GLOB frames RELATIVE "${OUT}_whole/vtk" "${OUT}_whole/vtk/*")
file(GLOB resumedFrames RELATIVE "${OUT}/vtk" "${OUT}/vtk/*")
list(SORT frames)
list(SORT resumedFrames)
if(NOT series OR NOT frames STREQUAL resumedFrames)
    message(FATAL_ERROR "the resumed run's vtk/ holds other files:\n${resumedFrames}\n---\n${frames}")
endif()
foreach(pvd IN LISTS series)
    file(READ "${OUT}/vtk/${pvd}" resumedPvd)
    file(READ "${OUT}_whole/vtk/${pvd}" wholePvd)
    if(NOT resumedPvd STREQUAL wholePvd)
        message(FATAL_ERROR "stopped and resumed, vtk/${pvd} differs:\n${resumedPvd}\n---\n${wholePvd}")
    endif()
endforeach()
foreach(index 000000 000001 000002 000003 000004 000005 000006 000007 000008)
    expect_csv("${OUT}/profiles/outline_${index}.csv" "x_m,y_m" 4 "^${metre},${metre}$")
endforeach()
if(EXISTS "${OUT}/profiles/outline_000009.csv" OR EXISTS "${OUT}/profiles/pore_pressure_failure_plane_000000.csv")
    message(FATAL_ERROR "a dry run to 2 tau_c writes outlines 0 to 8 and no pore pressure")
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
message(STATUS "ok: run to 1.75 tau_c, on to 2, back to 1.75 and resumed to 2: same series, summary and .pvd; "
               "submerged: ${fluidPoints} of 64 failure-plane points in the fluid")
