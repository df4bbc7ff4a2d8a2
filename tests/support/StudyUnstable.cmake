# `lbdem study` records a run stopped by the stability guard as "unstable" and goes on: the lid-
# driven cavity at tau - 0.5 = 1e-4 and lid Mach 0.17 (flow.reynolds = 0 imposes both) diverges
# within 400 steps with BGK, while MRT + LES, and BGK at tau = 0.8, stay bounded (Krueger et al.,
# The Lattice Boltzmann Method, 2017, sec. 10.6: BGK loses stability as tau -> 1/2). The study
# exits 0, keeps the guard's diagnosis, maps the cell as unstable and skips it when called again.
# Usage: cmake -DLBDEM=... -DCASE=... -DOUT=... -P this.
include("${CMAKE_CURRENT_LIST_DIR}/StudyChecks.cmake")
file(REMOVE_RECURSE "${OUT}")
set(args study "${CASE}" --vary fluid.collision=bgk,mrt_les --vary flow.tau=0.5001,0.8
    --set flow.reynolds=0 --set flow.lattice_velocity=0.1 --set flow.steps=400 --out "${OUT}")
lbdem_run_ok(out "${LBDEM}" ${args}) # an unstable run must not fail the study
if(NOT out MATCHES "fluid\\.collision=bgk,flow\\.tau=0\\.5001 unstable after [^\n]*: step [0-9]+: the fluid diverged")
    message(FATAL_ERROR "no 'unstable' progress line with the diagnosis: ${out}")
endif()
study_read_rows("${OUT}" 4 rows)
list(GET rows 1 bgk_low)
if(NOT bgk_low MATCHES "^bgk,0\\.5001,unstable,.*\"step [0-9]+: the fluid diverged[^\"]*tau - 0\\.5 = 0\\.0001")
    message(FATAL_ERROR "the BGK run at tau = 0.5001 is not recorded as unstable with its diagnosis: ${bgk_low}")
endif()
foreach(index 2 3 4)
    list(GET rows ${index} row)
    if(NOT row MATCHES "^[a-z_]+,[0-9.]+,finished,")
        message(FATAL_ERROR "row ${index} should have finished: ${row}")
    endif()
endforeach()
file(READ "${OUT}/study_map.md" map)
foreach(line "\\| bgk \\| unstable \\| bounded \\|" "\\| mrt_les \\| bounded \\| bounded \\|")
    if(NOT map MATCHES "${line}")
        message(FATAL_ERROR "study_map.md lacks '${line}': ${map}")
    endif()
endforeach()
lbdem_run_ok(again "${LBDEM}" ${args})
if(NOT again MATCHES "skip +fluid\\.collision=bgk,flow\\.tau=0\\.5001 \\(unstable\\)")
    message(FATAL_ERROR "a second call must skip the unstable run: ${again}")
endif()
message(STATUS "ok: ${bgk_low}")
