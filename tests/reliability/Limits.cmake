# No input makes a command hang or grow without bound: --until-tc must be a time within the case
# (inf, 1e308, 0, negative, nan refused), and a case or sweep file must be a regular file of at
# most 1 MiB (a FIFO with no writer, /dev/zero, an oversized file refused within a second) in
# every command that reads one. Each refusal: exit 2 and one sentence.
# Usage: cmake -DLBDEM=... -DCASE=default.toml -DOUT=... -P this.
file(REMOVE_RECURSE "${OUT}")
file(MAKE_DIRECTORY "${OUT}")
include("${CMAKE_CURRENT_LIST_DIR}/../support/CommandChecks.cmake")
set(small --set grains.count=150 --set grains.packing=0.79 --set fluid.enabled=false
    --set run.end_tc=0.5 --set run.output_interval_tc=0.25)

# --until-tc: run (before anything is written) and resume alike.
foreach(until inf 1e308 0 -1 nan 0.75)
    lbdem_expect_exit(2 MATCHES "--until-tc" COMMAND "${LBDEM}" run "${CASE}" ${small}
                      --until-tc ${until} --out "${OUT}/until" --quiet TIMEOUT 60)
    if(EXISTS "${OUT}/until")
        message(FATAL_ERROR "--until-tc ${until}: a refused run must create no output folder")
    endif()
endforeach()
lbdem_run_ok(ignored "${LBDEM}" run "${CASE}" ${small} --until-tc 0.25 --out "${OUT}/stopped" --quiet)
foreach(until inf -0.5 nan 1e308)
    lbdem_expect_exit(2 MATCHES "--until-tc" COMMAND "${LBDEM}" resume "${OUT}/stopped"
                      --until-tc ${until} --quiet TIMEOUT 60)
endforeach()

# Runs `lbdem ARGN`; fails unless it exits 2 with one sentence matching pattern within 5 s.
function(expect_quick_refusal pattern)
    string(TIMESTAMP start "%s%f")
    lbdem_expect_exit(2 MATCHES "${pattern}" COMMAND "${LBDEM}" ${ARGN} TIMEOUT 10)
    string(TIMESTAMP end "%s%f")
    math(EXPR elapsedMs "(${end} - ${start}) / 1000")
    if(elapsedMs GREATER 5000)
        message(FATAL_ERROR "'${ARGN}' took ${elapsedMs} ms to refuse its input")
    endif()
endfunction()

# /dev/zero (a device that never ends), within a second as the acceptance asks.
string(TIMESTAMP start "%s%f")
lbdem_expect_exit(2 MATCHES "/dev/zero is a device" COMMAND "${LBDEM}" info /dev/zero TIMEOUT 10)
string(TIMESTAMP end "%s%f")
math(EXPR elapsedMs "(${end} - ${start}) / 1000")
if(elapsedMs GREATER 1000)
    message(FATAL_ERROR "lbdem info /dev/zero took ${elapsedMs} ms")
endif()
# A FIFO nobody writes to, in every command that reads a case or a sweep file.
set(fifo "${OUT}/case.fifo")
execute_process(COMMAND mkfifo "${fifo}" RESULT_VARIABLE code)
if(NOT code EQUAL 0)
    message(FATAL_ERROR "mkfifo failed (${code})")
endif()
expect_quick_refusal("case\\.fifo is a FIFO" info "${fifo}")
expect_quick_refusal("case\\.fifo is a FIFO" run "${fifo}" --out "${OUT}/fifo_run" --quiet)
expect_quick_refusal("case\\.fifo is a FIFO" study "${fifo}" --vary fluid.resolution=4,5
                     --out "${OUT}/fifo_study" --quiet)
expect_quick_refusal("case\\.fifo is a FIFO" sweep "${fifo}" --out "${OUT}/fifo_sweep" --quiet)
expect_quick_refusal("case\\.fifo is a FIFO" bench --case "${fifo}")
expect_quick_refusal("/dev/zero is a device" run /dev/zero --out "${OUT}/zero_run" --quiet)
file(WRITE "${OUT}/fifo_sweep.toml" "sweep = 1\nname = \"f\"\ncases = [\"case.fifo\"]\n")
expect_quick_refusal("case\\.fifo is a FIFO" sweep "${OUT}/fifo_sweep.toml" --out "${OUT}/fifo_sweep2"
                     --quiet)
# A file over the limit, even one that would parse (comments).
string(REPEAT "# a comment line of a case file that is far too long to be a real one\n" 16000 filler)
file(WRITE "${OUT}/huge.toml" "schema = 1\n${filler}")
expect_quick_refusal("huge\\.toml holds [0-9]+ bytes, more than the 1048576" info "${OUT}/huge.toml")
foreach(path fifo_run study fifo_study fifo_sweep fifo_sweep2 zero_run)
    if(EXISTS "${OUT}/${path}")
        message(FATAL_ERROR "a refused command created ${OUT}/${path}")
    endif()
endforeach()
message(STATUS "ok: --until-tc bounded; FIFOs, devices and oversized files refused at once")
