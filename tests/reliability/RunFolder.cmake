# `lbdem run` never replaces a run silently: a second run into a finished run's folder exits 2
# and leaves every file as it was; a case refused after planning writes nothing even with
# --force; --force replaces the run and removes its old frames and profiles first.
# Usage: cmake -DLBDEM=... -DCASE=default.toml -DOUT=... -P this.
file(REMOVE_RECURSE "${OUT}")
set(small --set grains.count=150 --set grains.packing=0.79 --set fluid.enabled=false
    --set run.end_tc=0.5 --set run.output_interval_tc=0.25)

# The name and SHA-256 of every file under dir, one per line.
function(fingerprint dir result)
    file(GLOB_RECURSE files RELATIVE "${dir}" "${dir}/*")
    list(SORT files)
    set(text "")
    foreach(f IN LISTS files)
        file(SHA256 "${dir}/${f}" sum)
        string(APPEND text "${f} ${sum}\n")
    endforeach()
    set(${result} "${text}" PARENT_SCOPE)
endfunction()

execute_process(COMMAND "${LBDEM}" run "${CASE}" ${small} --out "${OUT}" --quiet RESULT_VARIABLE code ERROR_VARIABLE err)
if(NOT code EQUAL 0)
    message(FATAL_ERROR "first run failed (${code}): ${err}")
endif()
fingerprint("${OUT}" before)
execute_process(COMMAND "${LBDEM}" run "${CASE}" ${small} --out "${OUT}" --quiet RESULT_VARIABLE code ERROR_VARIABLE err)
if(NOT code EQUAL 2 OR NOT err MATCHES "holds a run; use lbdem resume .*--force to replace it")
    message(FATAL_ERROR "a second run into a finished run must exit 2 naming resume and --force (${code}): ${err}")
endif()
fingerprint("${OUT}" after)
if(NOT before STREQUAL after)
    message(FATAL_ERROR "the refused run changed the folder:\n${before}---\n${after}")
endif()
# A case that cannot be built (the column does not fit the domain) writes nothing, even forced.
execute_process(COMMAND "${LBDEM}" run "${CASE}" ${small} --set domain.width_m=0.02 --out "${OUT}" --force --quiet
                RESULT_VARIABLE code ERROR_VARIABLE err)
fingerprint("${OUT}" after)
if(NOT code EQUAL 2 OR NOT before STREQUAL after)
    message(FATAL_ERROR "a case refused after planning must leave the folder as it was (${code}): ${err}")
endif()
# --force replaces the run: stale frames and profiles of the old one are gone.
file(WRITE "${OUT}/vtk/particles_000099.vtu" "stale")
file(WRITE "${OUT}/profiles/outline_000099.csv" "stale")
file(WRITE "${OUT}/notes.txt" "kept")
execute_process(COMMAND "${LBDEM}" run "${CASE}" ${small} --set run.end_tc=0.25 --out "${OUT}" --force --quiet
                RESULT_VARIABLE code ERROR_VARIABLE err)
if(NOT code EQUAL 0)
    message(FATAL_ERROR "--force run failed (${code}): ${err}")
endif()
if(EXISTS "${OUT}/vtk/particles_000099.vtu" OR EXISTS "${OUT}/profiles/outline_000099.csv"
   OR NOT EXISTS "${OUT}/notes.txt")
    message(FATAL_ERROR "--force must remove the old run's outputs (and only those)")
endif()
file(STRINGS "${OUT}/timeseries.csv" rows)
list(LENGTH rows count)
if(NOT count EQUAL 3) # header + t/tc = 0, 0.25
    message(FATAL_ERROR "the replaced run's timeseries.csv holds ${count} lines, expected 3")
endif()
message(STATUS "ok: an existing run is refused, kept, and replaced only with --force")
