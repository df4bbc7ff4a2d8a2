# A small submerged column run on 1 and on 2 threads writes the same timeseries.csv byte for byte:
# every sum of the coupled step (DEM contact forces, hydrodynamic loads, diagnostics) is taken in
# an order that does not depend on the thread count. The collapse is chaotic, so a difference in
# the last bit of one force grows into a visible difference within a fraction of tau_c.
# Usage: cmake -DLBDEM=... -DCASE=... -DOUT=... -P this.
file(REMOVE_RECURSE "${OUT}_1" "${OUT}_2")
set(small --set grains.count=200 --set grains.packing=0.79 --set fluid.resolution=4
    --set domain.width_m=0.08 --set domain.height_m=0.04
    --set run.end_tc=1.5 --set run.output_interval_tc=0.125 --set output.vtk=false
    --set output.checkpoint_interval_tc=0)
foreach(threads 1 2)
    execute_process(COMMAND "${LBDEM}" run "${CASE}" --out "${OUT}_${threads}" --quiet ${small}
                            --set run.threads=${threads}
                    RESULT_VARIABLE code ERROR_VARIABLE err)
    if(NOT code EQUAL 0)
        message(FATAL_ERROR "run on ${threads} thread(s) failed (${code}): ${err}")
    endif()
endforeach()
file(READ "${OUT}_1/timeseries.csv" one)
file(READ "${OUT}_2/timeseries.csv" two)
if(NOT one STREQUAL two)
    message(FATAL_ERROR "timeseries.csv differs between 1 and 2 threads:\n${one}\n---\n${two}")
endif()
string(LENGTH "${one}" size)
message(STATUS "ok: 1 and 2 threads give the same timeseries.csv (${size} bytes)")
