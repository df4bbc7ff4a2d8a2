# Command checks shared by the CMake-script tests: include() this file, then call the functions.

# lbdem_expect_exit(CODE MATCHES REGEX... COMMAND ARG... [TIMEOUT s] [NO_STDOUT]): runs the
# command; fails unless it exits with CODE and its stderr is one line, under 1500 bytes, matching
# every REGEX (the bad-input contract is CODE 2 and one sentence); with NO_STDOUT, stdout must be
# empty as well. TIMEOUT defaults to 120 s.
function(lbdem_expect_exit expected)
    cmake_parse_arguments(PARSE_ARGV 1 ARG "NO_STDOUT" "TIMEOUT" "MATCHES;COMMAND")
    if(NOT ARG_TIMEOUT)
        set(ARG_TIMEOUT 120)
    endif()
    execute_process(COMMAND ${ARG_COMMAND} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err
                    TIMEOUT ${ARG_TIMEOUT})
    list(JOIN ARG_COMMAND " " what)
    set(what "'${what}'")
    if(NOT code STREQUAL "${expected}")
        message(FATAL_ERROR "${what}: exit '${code}', expected ${expected}: ${out}${err}")
    endif()
    foreach(pattern IN LISTS ARG_MATCHES)
        if(NOT err MATCHES "${pattern}")
            message(FATAL_ERROR "${what}: message does not match '${pattern}': ${err}")
        endif()
    endforeach()
    string(REGEX MATCHALL "\n" newlines "${err}")
    list(LENGTH newlines count)
    string(LENGTH "${err}" length)
    if(NOT count EQUAL 1 OR length GREATER 1500)
        message(FATAL_ERROR "${what}: expected one line under 1500 bytes, got ${count} lines, ${length} bytes: ${err}")
    endif()
    if(ARG_NO_STDOUT AND NOT out STREQUAL "")
        message(FATAL_ERROR "${what}: expected nothing on stdout: ${out}")
    endif()
    message(STATUS "ok: ${err}")
endfunction()

# lbdem_run_ok(OUT ARG...): runs the command; fails unless it exits with 0; its stdout goes to the
# variable named OUT.
function(lbdem_run_ok out)
    execute_process(COMMAND ${ARGN} RESULT_VARIABLE code OUTPUT_VARIABLE stdout ERROR_VARIABLE stderr)
    if(NOT code EQUAL 0)
        list(JOIN ARGN " " command)
        message(FATAL_ERROR "'${command}' failed (${code}):\n${stdout}\n${stderr}")
    endif()
    set(${out} "${stdout}" PARENT_SCOPE)
endfunction()

# lbdem_expect_in(WHAT TEXT EXPECTED...): fails unless TEXT holds each EXPECTED string.
function(lbdem_expect_in what text)
    foreach(expected ${ARGN})
        string(FIND "${text}" "${expected}" at)
        if(at EQUAL -1)
            message(FATAL_ERROR "${what} lacks '${expected}':\n${text}")
        endif()
    endforeach()
endfunction()
