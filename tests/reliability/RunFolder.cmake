# `lbdem run` never replaces a run silently: a second run into a finished run's folder exits 2
# and leaves every file as it was; a case refused after planning writes nothing even with
# --force; --force replaces the run and removes its old frames and profiles first, but nothing
# else (a user's file in vtk/ stays, an edited case.toml is refused); a folder that holds no run
# but a user's files (their own case.toml, a frames/ folder, notes) is refused, with --force or
# without and with --out . among them, and nothing in it is removed.
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
file(WRITE "${OUT}/vtk/view.pvsm" "a ParaView state of one's own")
execute_process(COMMAND "${LBDEM}" run "${CASE}" ${small} --set run.end_tc=0.25 --out "${OUT}" --force --quiet
                RESULT_VARIABLE code ERROR_VARIABLE err)
if(NOT code EQUAL 0)
    message(FATAL_ERROR "--force run failed (${code}): ${err}")
endif()
if(EXISTS "${OUT}/vtk/particles_000099.vtu" OR EXISTS "${OUT}/profiles/outline_000099.csv"
   OR NOT EXISTS "${OUT}/notes.txt" OR NOT EXISTS "${OUT}/vtk/view.pvsm")
    message(FATAL_ERROR "--force must remove the old run's outputs (and only those)")
endif()
file(STRINGS "${OUT}/timeseries.csv" rows)
list(LENGTH rows count)
if(NOT count EQUAL 3) # header + t/tc = 0, 0.25
    message(FATAL_ERROR "the replaced run's timeseries.csv holds ${count} lines, expected 3")
endif()
# An edited case.toml in a run's folder is no longer the run's: --force refuses to replace it.
file(APPEND "${OUT}/case.toml" "# a note of one's own\n")
fingerprint("${OUT}" before)
execute_process(COMMAND "${LBDEM}" run "${CASE}" ${small} --out "${OUT}" --force --quiet
                RESULT_VARIABLE code ERROR_VARIABLE err)
fingerprint("${OUT}" after)
if(NOT code EQUAL 2 OR NOT err MATCHES "case\\.toml was changed since its run wrote it" OR NOT before STREQUAL after)
    message(FATAL_ERROR "--force over an edited case.toml must exit 2 and change nothing (${code}): ${err}")
endif()

# A user's own folder: a commented case.toml, a frames/ folder and notes, but no run.
set(user "${OUT}_user")
file(REMOVE_RECURSE "${user}")
file(READ "${CASE}" text)
file(WRITE "${user}/case.toml" "# my own case, with my comments\n${text}")
file(WRITE "${user}/frames/photo.png" "not a frame of a run")
file(WRITE "${user}/notes.txt" "mine")
fingerprint("${user}" before)
foreach(force "" "--force")
    execute_process(COMMAND "${LBDEM}" run case.toml ${small} --out . ${force} --quiet
                    WORKING_DIRECTORY "${user}" RESULT_VARIABLE code ERROR_VARIABLE err)
    fingerprint("${user}" after)
    if(NOT code EQUAL 2 OR NOT err MATCHES "holds (no run|case\\.toml)" OR NOT before STREQUAL after)
        message(FATAL_ERROR "lbdem run case.toml --out . ${force} in a user's folder must exit 2 "
                            "and change nothing (${code}): ${err}\n${before}---\n${after}")
    endif()
endforeach()
# A folder with only a file a run does not write: --force is refused and removes nothing.
file(REMOVE_RECURSE "${user}")
file(WRITE "${user}/data.csv" "1,2,3\n")
execute_process(COMMAND "${LBDEM}" run "${CASE}" ${small} --out "${user}" --force --quiet
                RESULT_VARIABLE code ERROR_VARIABLE err)
file(GLOB left RELATIVE "${user}" "${user}/*")
if(NOT code EQUAL 2 OR NOT err MATCHES "holds no run.*data\\.csv.*--force replaces only a run" OR NOT left STREQUAL "data.csv")
    message(FATAL_ERROR "--force into a folder holding a user's file must exit 2 and change nothing (${code}): ${err} [${left}]")
endif()
message(STATUS "ok: an existing run is refused, kept, and replaced only with --force; a user's folder is never touched")
