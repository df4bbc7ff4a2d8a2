# One golden run: runs CASE briefly with ARGS and compares its timeseries.csv with the committed
# golden/NAME.csv byte for byte (README.md in this folder says why and how to regenerate).
# Usage: cmake -DLBDEM=portable-lbdem -DCOMPARE=... -DCASE=... -DNAME=...
#              -DARGS=a;b -DGOLDEN=dir -DPACKINGS=dir -DOUT=dir -DCOMPILER=text -P GoldenRun.cmake
# Grains start from the committed packings in PACKINGS: a packing settled by another build would
# differ at round-off, and the contacts amplify that.
if(NOT EXISTS "${LBDEM}")
    message(FATAL_ERROR "${NAME}: no portable lbdem at ${LBDEM}; build it with "
                        "'cmake --preset portable && cmake --build --preset portable' (building a "
                        "native tree does it)")
endif()
set(run_dir "${OUT}/run")
set(cache_dir "${OUT}/packings")
file(REMOVE_RECURSE "${OUT}")
file(MAKE_DIRECTORY "${cache_dir}")
file(GLOB committed "${PACKINGS}/*.txt")
if(committed)
    file(COPY ${committed} DESTINATION "${cache_dir}")
endif()

execute_process(COMMAND ${CMAKE_COMMAND} -E env LBDEM_CACHE_DIR=${cache_dir} OMP_WAIT_POLICY=passive
                        "${LBDEM}" run "${CASE}" --out "${run_dir}" --quiet ${ARGS}
                RESULT_VARIABLE code ERROR_VARIABLE err)
if(NOT code EQUAL 0)
    message(FATAL_ERROR "${NAME}: the run failed (exit ${code}): ${err}")
endif()

set(golden_csv "${GOLDEN}/${NAME}.csv")
set(golden_compiler_file "${GOLDEN}/compiler.txt")
file(GLOB used "${cache_dir}/*.txt")
if(DEFINED ENV{LBDEM_REGENERATE_GOLDEN})
    file(COPY_FILE "${run_dir}/timeseries.csv" "${golden_csv}")
    file(WRITE "${golden_compiler_file}" "${COMPILER}\n")
    foreach(packing IN LISTS used)
        get_filename_component(leaf "${packing}" NAME)
        if(NOT EXISTS "${PACKINGS}/${leaf}")
            file(COPY "${packing}" DESTINATION "${PACKINGS}")
            message(STATUS "${NAME}: committed packing ${leaf} added")
        endif()
    endforeach()
    message(STATUS "${NAME}: golden time series regenerated with ${COMPILER}")
    return()
endif()

foreach(packing IN LISTS used)
    get_filename_component(leaf "${packing}" NAME)
    if(NOT EXISTS "${PACKINGS}/${leaf}")
        message(FATAL_ERROR "${NAME}: the run settled a new packing (${leaf}) instead of reading a "
                            "committed one, so its start depends on this processor; regenerate the "
                            "golden runs deliberately (tests/regression/README.md)")
    endif()
    # A committed packing that fails its checksum is settled again and rewritten, not read.
    file(SHA256 "${packing}" used_sum)
    file(SHA256 "${PACKINGS}/${leaf}" committed_sum)
    if(NOT used_sum STREQUAL committed_sum)
        message(FATAL_ERROR "${NAME}: the committed packing ${leaf} was not read but settled again "
                            "(is its checksum line missing or wrong?); regenerate the golden runs "
                            "deliberately (tests/regression/README.md)")
    endif()
endforeach()
if(NOT EXISTS "${golden_csv}" OR NOT EXISTS "${golden_compiler_file}")
    message(FATAL_ERROR "${NAME}: no golden time series ${golden_csv} (tests/regression/README.md)")
endif()
file(STRINGS "${golden_compiler_file}" golden_compiler LIMIT_COUNT 1)
if(NOT golden_compiler STREQUAL COMPILER)
    message(STATUS "golden runs skipped: they were written by ${golden_compiler} and this build "
                   "uses ${COMPILER}, whose code may round differently (tests/regression/README.md)")
    return()
endif()
execute_process(COMMAND "${COMPARE}" "${golden_csv}" "${run_dir}/timeseries.csv"
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0)
    message(FATAL_ERROR "${NAME}: timeseries.csv differs from the golden run: ${err}${out}")
endif()
message(STATUS "ok: ${NAME}: ${out}")
