# `lbdem sweep` end to end: a case stopped part way is resumed, a fresh one is run, the combined
# table is written, and a second sweep skips both finished cases.
# Usage: cmake -DLBDEM=... -DSWEEP=... -DCASE=<the first case of SWEEP> -DOUT=... -P this.
file(REMOVE_RECURSE "${OUT}")
set(small --set grains.count=150 --set run.end_tc=1 --set run.output_interval_tc=0.25)

include("${CMAKE_CURRENT_LIST_DIR}/CommandChecks.cmake")

# The first case stops at 0.5 tau_c, as if the sweep had been killed there.
lbdem_run_ok(ignored "${LBDEM}" run "${CASE}" --out "${OUT}/loose_0deg_dry" --until-tc 0.5 --quiet ${small})
lbdem_run_ok(first "${LBDEM}" sweep "${SWEEP}" --out "${OUT}" --jobs 2)
lbdem_expect_in("the sweep's output" "${first}" "resume  loose_0deg_dry" "run     loose_5deg_dry"
                "loose_0deg_dry finished" "loose_5deg_dry finished" "wrote ${OUT}/sweep.csv"
                "wrote ${OUT}/sweep.md")
foreach(name loose_0deg_dry loose_5deg_dry)
    file(READ "${OUT}/${name}/summary.json" summary)
    if(NOT summary MATCHES "\"finished\": true")
        message(FATAL_ERROR "${name} did not finish: ${summary}")
    endif()
    file(STRINGS "${OUT}/${name}/timeseries.csv" rows)
    list(LENGTH rows count)
    if(NOT count EQUAL 6) # header + t/tc = 0, 0.25, 0.5, 0.75, 1: the resumed case holds each once
        message(FATAL_ERROR "${name}: expected 6 lines in timeseries.csv, got ${count}:\n${rows}")
    endif()
endforeach()
file(STRINGS "${OUT}/sweep.csv" table)
list(LENGTH table count)
if(NOT count EQUAL 3)
    message(FATAL_ERROR "sweep.csv: expected a header and 2 rows, got:\n${table}")
endif()

# A second sweep finds both cases finished and runs nothing.
lbdem_run_ok(second "${LBDEM}" sweep "${SWEEP}" --out "${OUT}" --jobs 2)
foreach(name loose_0deg_dry loose_5deg_dry)
    string(FIND "${second}" "skip    ${name} (finished)" at)
    if(at EQUAL -1)
        message(FATAL_ERROR "the second sweep did not skip ${name}:\n${second}")
    endif()
endforeach()
