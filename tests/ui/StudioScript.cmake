# Checks the studio's command-line contract. MODE=screenshot: `lbdem-studio CASE --run-steps N
# --screenshot FILE --quit` exits 0 and writes a PNG. MODE=bad_case: a bad case file exits 2 with
# one line naming the file, the line and the suggested key.
# Usage: cmake -DSTUDIO=... -DCASE=... -DMODE=... [-DOUT=...] [-DARGS=...] -P StudioScript.cmake
include("${CMAKE_CURRENT_LIST_DIR}/../support/CommandChecks.cmake")
if(MODE STREQUAL "screenshot")
    file(REMOVE "${OUT}")
    execute_process(COMMAND "${STUDIO}" "${CASE}" ${ARGS} --run-steps 20 --screenshot "${OUT}" --quit
                    RESULT_VARIABLE code ERROR_VARIABLE err OUTPUT_VARIABLE out TIMEOUT 240)
    if(NOT code EQUAL 0)
        message(FATAL_ERROR "expected exit code 0, got ${code}: ${err}")
    endif()
    if(NOT EXISTS "${OUT}")
        message(FATAL_ERROR "no screenshot at ${OUT}: ${out} ${err}")
    endif()
    file(SIZE "${OUT}" size)
    if(size LESS 20000)
        message(FATAL_ERROR "screenshot ${OUT} is only ${size} bytes: a blank window?")
    endif()
    message(STATUS "ok: ${out}")
elseif(MODE STREQUAL "bad_case")
    get_filename_component(name "${CASE}" NAME)
    lbdem_expect_exit(2 MATCHES "${name}:5:" "fluid\\.tau'" TIMEOUT 60
                      COMMAND "${STUDIO}" "${CASE}" --run-steps 1 --quit)
else()
    message(FATAL_ERROR "unknown MODE '${MODE}'")
endif()
