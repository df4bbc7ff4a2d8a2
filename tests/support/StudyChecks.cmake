# Checks shared by the `lbdem study` test scripts (include()d by them), with CommandChecks.cmake.
include("${CMAKE_CURRENT_LIST_DIR}/CommandChecks.cmake")

# Fail unless OUT holds study.csv, study.md, the extra files named, and study.png when VIS is on.
function(study_expect_files out vis)
    set(expected study.csv study.md ${ARGN})
    if(vis)
        list(APPEND expected study.png)
    endif()
    foreach(name IN LISTS expected)
        if(NOT EXISTS "${out}/${name}")
            message(FATAL_ERROR "${out}/${name} was not written")
        endif()
    endforeach()
endfunction()

# Read OUT/study.csv into the list ROWS_VAR (header first); fail unless it has a header and RUNS rows.
function(study_read_rows out runs rows_var)
    file(STRINGS "${out}/study.csv" rows)
    list(LENGTH rows count)
    math(EXPR wanted "${runs} + 1")
    if(NOT count EQUAL wanted)
        message(FATAL_ERROR "expected a header and ${runs} rows in study.csv, got ${count}: ${rows}")
    endif()
    set(${rows_var} "${rows}" PARENT_SCOPE)
endfunction()
