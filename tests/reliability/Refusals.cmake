# What a hostile user types gets exit 2 and one sentence, never a signal, a stack trace or a
# folder outside results/: an unstable DEM step, unsafe names, a folder as CASE, zero grains,
# zero gravity, a file as --out, a case too big for the machine, binary and huge keys; a run the
# stability guard stops exits 3 with its diagnosis on a line of its own; lbdem-studio --help
# needs no display. Usage: cmake -DLBDEM=... -DCASE=default.toml -DFLOW=stability.toml
# -DOUT=... [-DSTUDIO=...] -P this.
file(REMOVE_RECURSE "${OUT}")
file(MAKE_DIRECTORY "${OUT}")
set(small --set grains.count=150 --set grains.packing=0.79 --set fluid.resolution=4)

include("${CMAKE_CURRENT_LIST_DIR}/../support/CommandChecks.cmake")

# Runs lbdem with ARGN; fails unless it exits with `expected` and stderr is one line matching
# `pattern`.
function(expect_exit expected pattern)
    lbdem_expect_exit(${expected} MATCHES "${pattern}" COMMAND "${LBDEM}" ${ARGN})
endfunction()

# 1. One DEM sub-step per fluid step is far beyond the DEM's stability limit: refused by the
#    planner (it crashed in the neighbour grid), in info and run alike, and nothing is created.
expect_exit(2 "coupling\\.substeps.*stability limit" info "${CASE}" --set coupling.substeps=1)
expect_exit(2 "coupling\\.substeps.*stability limit" run "${CASE}" --set coupling.substeps=1
            --set run.end_tc=0.5 --out "${OUT}/substeps" --quiet)
if(EXISTS "${OUT}/substeps")
    message(FATAL_ERROR "a refused case must create no output folder")
endif()
# 9. A case name becomes a folder: paths, empty names and odd characters are refused.
foreach(name "../../x" "" "a/b" "..hidden" "x y")
    expect_exit(2 "key 'name'" info "${CASE}" "--set" "name=${name}")
endforeach()
# 10. A folder given as CASE, zero grains, zero gravity, a file as --out, a damaged key.
expect_exit(2 "is a folder, not a case file" info "${OUT}")
expect_exit(2 "grains\\.count" info "${CASE}" --set grains.count=0)
expect_exit(2 "domain\\.gravity_m_s2" info "${CASE}" --set domain.gravity_m_s2=0)
file(WRITE "${OUT}/a_file" "")
expect_exit(2 "is a file" run "${CASE}" ${small} --out "${OUT}/a_file" --quiet)
string(REPEAT "k" 200000 hugeKey)
file(WRITE "${OUT}/huge_key.toml" "schema = 1\n${hugeKey} = 1\n")
expect_exit(2 "more bytes" info "${OUT}/huge_key.toml")
string(ASCII 1 7 27 binary)
file(WRITE "${OUT}/binary.toml" "schema = 1\nname = \"a${binary}b\"\n")
foreach(args "${OUT}/binary.toml" "${CASE};--set;grains.count=1${binary}")
    execute_process(COMMAND "${LBDEM}" info ${args} RESULT_VARIABLE code ERROR_VARIABLE err)
    string(REGEX MATCH "[${binary}]" echoed "${err}")
    if(NOT code EQUAL 2 OR echoed)
        message(FATAL_ERROR "control characters in the input: exit ${code}, message must not echo them: ${err}")
    endif()
endforeach()
# 6. A lattice of 2e11 nodes: info warns, run refuses before allocating (it died of bad_alloc).
set(huge --set domain.width_m=100 --set domain.height_m=50 --set fluid.resolution=20)
execute_process(COMMAND "${LBDEM}" info "${CASE}" ${huge} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0 OR NOT out MATCHES "warning: the run needs about [0-9.]+ TiB of memory")
    message(FATAL_ERROR "info on a huge case must warn about memory (${code}): ${out}${err}")
endif()
expect_exit(2 "memory.*--force" run "${CASE}" ${huge} --out "${OUT}/huge" --quiet)
execute_process(COMMAND "${LBDEM}" info "${CASE}" --json RESULT_VARIABLE code OUTPUT_VARIABLE json)
string(JSON outputBytes GET "${json}" output_bytes)
string(JSON memoryBytes GET "${json}" memory_bytes)
if(NOT code EQUAL 0 OR outputBytes LESS 1000000 OR outputBytes GREATER 250000000 OR memoryBytes LESS 1000000)
    message(FATAL_ERROR "default case: plan.json output_bytes ${outputBytes} must be under 250 MB (both checkpoints of a replacement counted), memory ${memoryBytes}")
endif()
# 10. A run the stability guard stops exits 3, its diagnosis on a line of its own (not after the
#     progress line), and it can be resumed from the checkpoint written at t = 0 (8).
execute_process(COMMAND "${LBDEM}" run "${FLOW}" --set fluid.collision=bgk --out "${OUT}/unstable"
                RESULT_VARIABLE code ERROR_VARIABLE err TIMEOUT 300)
if(NOT code EQUAL 3 OR NOT err MATCHES "(^|\n)lbdem: the simulation stopped: ")
    message(FATAL_ERROR "a run stopped by the guard: exit ${code} (expected 3), diagnosis on its own line: ${err}")
endif()
if(NOT EXISTS "${OUT}/unstable/checkpoint.h5")
    message(FATAL_ERROR "a run stopped before its first checkpoint interval left no checkpoint (t = 0)")
endif()
if(STUDIO)
    execute_process(COMMAND ${CMAKE_COMMAND} -E env --unset=DISPLAY --unset=WAYLAND_DISPLAY QT_QPA_PLATFORM=xcb
                            "${STUDIO}" --help
                    RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 60)
    if(NOT code EQUAL 0 OR NOT out MATCHES "Usage")
        message(FATAL_ERROR "lbdem-studio --help without a display: exit ${code}: ${out}${err}")
    endif()
endif()
message(STATUS "ok: every hostile input refused with one sentence")
