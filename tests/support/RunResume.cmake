# `lbdem run --until-tc` then `lbdem resume`: the resumed run finishes, and timeseries.csv holds
# each output time once. Usage: cmake -DLBDEM=... -DCASE=... -DOUT=... -P this.
file(REMOVE_RECURSE "${OUT}")
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
file(STRINGS "${OUT}/timeseries.csv" rows)
list(LENGTH rows count)
if(NOT count EQUAL 6) # header + t/tc = 0, 0.25, 0.5, 0.75, 1
    message(FATAL_ERROR "expected 6 lines in timeseries.csv, got ${count}:\n${rows}")
endif()
message(STATUS "ok: run to 0.5 tau_c, resumed to 1 tau_c, ${count} lines")
