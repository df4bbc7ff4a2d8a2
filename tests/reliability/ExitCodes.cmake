# Exit codes and sentences that say what happened: `render` refuses a damaged VTU or VTI (exit 2,
# no blank picture); `resume` names the file and line of a damaged time-series row (exit 2, the
# folder left as it was); a run the stability guard stopped is `unstable` in the table of a sweep
# without seeds; a packing the generator cannot reach names its key.
# Usage: cmake -DLBDEM=... -DCASE=default.toml -DOUT=... -P this.
file(REMOVE_RECURSE "${OUT}")
file(MAKE_DIRECTORY "${OUT}")
include("${CMAKE_CURRENT_LIST_DIR}/../support/CommandChecks.cmake")
set(small --set grains.count=150 --set grains.packing=0.79 --set fluid.enabled=false
    --set run.end_tc=0.1 --set run.output_interval_tc=0.05 --set output.vtk_every=1)

# A stopped run with VTK frames 0 and 1 (where the build writes VTK).
lbdem_run_ok(ignored "${LBDEM}" run "${CASE}" ${small} --until-tc 0.05 --out "${OUT}/run" --quiet)

# 1. render: a truncated particles file, then a damaged fluid image beside an intact one.
execute_process(COMMAND "${LBDEM}" render --help RESULT_VARIABLE hasRender OUTPUT_QUIET ERROR_QUIET)
if(hasRender EQUAL 0 AND EXISTS "${OUT}/run/vtk/particles_000001.vtu")
    file(COPY "${OUT}/run/" DESTINATION "${OUT}/damaged")
    file(READ "${OUT}/run/vtk/particles_000001.vtu" text)
    string(LENGTH "${text}" length)
    math(EXPR half "${length} / 2")
    string(SUBSTRING "${text}" 0 ${half} text)
    file(WRITE "${OUT}/damaged/vtk/particles_000001.vtu" "${text}")
    lbdem_expect_exit(2 MATCHES "particles_000001\\.vtu is damaged" COMMAND "${LBDEM}" render
                      "${OUT}/damaged" --png "${OUT}/damaged.png" --quiet TIMEOUT 300)
    file(WRITE "${OUT}/damaged/vtk/fluid_000000.vti"
         "<?xml version=\"1.0\"?>\n<VTKFile type=\"ImageData\" version=\"1.0\">\n<ImageData WholeExtent=\"0 9 0")
    lbdem_expect_exit(2 MATCHES "fluid_000000\\.vti is damaged" COMMAND "${LBDEM}" render
                      "${OUT}/damaged" --png "${OUT}/damaged.png" --frame 0 --quiet TIMEOUT 300)
    if(EXISTS "${OUT}/damaged.png")
        message(FATAL_ERROR "render of a damaged frame left a picture")
    endif()
    lbdem_run_ok(ignored "${LBDEM}" render "${OUT}/run" --png "${OUT}/intact.png" --quiet)
endif()

# 2. resume: a time-series row damaged by hand stops it with the file and the line.
file(COPY "${OUT}/run/" DESTINATION "${OUT}/bad_row")
file(STRINGS "${OUT}/bad_row/timeseries.csv" rows)
list(GET rows 2 row)
string(REGEX REPLACE "^[^,]+" "oops" row "${row}")
list(REMOVE_AT rows 2)
list(INSERT rows 2 "${row}")
list(JOIN rows "\n" text)
file(WRITE "${OUT}/bad_row/timeseries.csv" "${text}\n")
file(SHA256 "${OUT}/bad_row/timeseries.csv" before)
lbdem_expect_exit(2 MATCHES "timeseries\\.csv:3: the cell 'oops' of column t_s is not a number"
                  COMMAND "${LBDEM}" resume "${OUT}/bad_row" --quiet)
file(SHA256 "${OUT}/bad_row/timeseries.csv" after)
if(NOT before STREQUAL after)
    message(FATAL_ERROR "a refused resume changed timeseries.csv")
endif()

# 3. A sweep without seeds: a run the guard stopped (summary.json with stop_reason) is unstable,
#    a run stopped by a signal or a kill (no stop_reason) unfinished.
file(WRITE "${OUT}/sweep.toml" "sweep = 1\nname = \"g\"\ncases = [\"${CASE}\", \"guard.toml\"]\n")
file(READ "${CASE}" text)
string(REGEX REPLACE "name = \"[^\"]*\"" "name = \"guard\"" text "${text}")
file(WRITE "${OUT}/guard.toml" "${text}")
file(MAKE_DIRECTORY "${OUT}/sweep/default" "${OUT}/sweep/guard")
file(WRITE "${OUT}/sweep/guard/summary.json"
     "{\"finished\": false, \"stop_reason\": \"the lattice became unstable at step 12\"}\n")
file(WRITE "${OUT}/sweep/default/summary.json" "{\"finished\": false}\n")
execute_process(COMMAND "${LBDEM}" sweep "${OUT}/sweep.toml" --out "${OUT}/sweep" --report --quiet
                RESULT_VARIABLE code ERROR_VARIABLE err)
file(READ "${OUT}/sweep/sweep.csv" csv)
if(NOT csv MATCHES "\nguard,[^,]*,[^,]*,[^,]*,unstable," OR NOT csv MATCHES "\ndefault,[^,]*,[^,]*,[^,]*,unfinished,")
    message(FATAL_ERROR "sweep.csv must say unstable for a guard-stopped run (${code}: ${err}):\n${csv}")
endif()

# 4. A packing fraction the generator cannot reach is refused naming the key.
lbdem_expect_exit(2 MATCHES "key 'grains\\.packing'" COMMAND "${LBDEM}" run "${CASE}" ${small}
                  --set grains.packing=0.9 --out "${OUT}/packing" --quiet)
message(STATUS "ok: damaged frames, damaged rows, guard-stopped runs and packings each say so")
