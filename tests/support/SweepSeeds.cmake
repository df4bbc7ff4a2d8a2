# `lbdem sweep` over packing seeds end to end: a sweep file with `seeds = [1, 2]` runs each of its
# two tiny cases once per seed into CASE_s1 and CASE_s2 (different packings), writes the spread per
# case (sweep.csv), one row per run (runs.csv) and the findings; --report gathers them again
# without running; --slurm without sbatch writes a job-array script whose tasks, started by hand,
# skip a finished run and redo a missing one; a seed listed twice is refused.
# Usage: cmake -DLBDEM=... -DSWEEP=<tiny_seeds.toml> -DBAD=<bad_seeds.toml> -DOUT=... -P this.
file(REMOVE_RECURSE "${OUT}")

include("${CMAKE_CURRENT_LIST_DIR}/CommandChecks.cmake")

set(runs loose_0deg_dry_s1 loose_0deg_dry_s2 loose_5deg_dry_s1 loose_5deg_dry_s2)
lbdem_run_ok(first "${LBDEM}" sweep "${SWEEP}" --out "${OUT}" --jobs 2 --progress-every 0)
foreach(run ${runs})
    lbdem_expect_in("the sweep's output" "${first}" "run     ${run}" "${run} finished")
    file(READ "${OUT}/${run}/summary.json" summary)
    if(NOT summary MATCHES "\"finished\": true")
        message(FATAL_ERROR "${run} did not finish: ${summary}")
    endif()
endforeach()
file(READ "${OUT}/loose_0deg_dry_s2/case.toml" case2)
lbdem_expect_in("loose_0deg_dry_s2/case.toml" "${case2}" "seed = 2")
# Two seeds, two packings: the columns differ from the first row on.
file(STRINGS "${OUT}/loose_0deg_dry_s1/timeseries.csv" series1 LIMIT_COUNT 2)
file(STRINGS "${OUT}/loose_0deg_dry_s2/timeseries.csv" series2 LIMIT_COUNT 2)
if("${series1}" STREQUAL "${series2}")
    message(FATAL_ERROR "seeds 1 and 2 gave the same column:\n${series1}")
endif()

file(READ "${OUT}/sweep.csv" table)
lbdem_expect_in("sweep.csv" "${table}" "runout_final_mean,runout_final_sd,runout_final_min,runout_final_max"
          "runout_at_3tc_mean" "froude_at_3tc_mean" "packing_final_mean" "\nloose_0deg_dry,0.79,0.0,dry,2,2,0,"
          "\nloose_5deg_dry,0.79,5.0,dry,2,2,0,")
file(STRINGS "${OUT}/runs.csv" rows)
list(LENGTH rows count)
if(NOT count EQUAL 5)
    message(FATAL_ERROR "runs.csv: expected a header and 4 runs, got:\n${rows}")
endif()
file(READ "${OUT}/findings.csv" findings)
lbdem_expect_in("findings.csv" "${findings}" "\"loose, dry: runout grows with slope\",0 deg to 5 deg,")
file(READ "${OUT}/sweep.md" md)
lbdem_expect_in("sweep.md" "${md}" "## Ensemble over packing seeds" "| loose_0deg_dry | 2 | 2 | 0 |" "## Findings"
          "| loose, dry: runout grows with slope | 0 deg to 5 deg | holds for " "## Runs" "| loose_5deg_dry_s2 |")

# --report gathers the same tables again and runs nothing.
file(REMOVE "${OUT}/sweep.csv" "${OUT}/findings.csv")
lbdem_run_ok(gathered "${LBDEM}" sweep "${SWEEP}" --out "${OUT}" --report)
lbdem_expect_in("--report's output" "${gathered}" "wrote ${OUT}/sweep.csv" "wrote ${OUT}/findings.csv")
string(FIND "${gathered}" "run     " at)
if(NOT at EQUAL -1)
    message(FATAL_ERROR "--report ran a case:\n${gathered}")
endif()

# --slurm without sbatch on PATH: the script is written and the way to submit it is said.
lbdem_run_ok(slurm ${CMAKE_COMMAND} -E env PATH=/nonexistent "${LBDEM}" sweep "${SWEEP}" --out "${OUT}" --slurm
       --partition short --time 0:10:00 --cpus-per-task 2)
lbdem_expect_in("--slurm's output" "${slurm}" "wrote ${OUT}/sweep.sbatch (4 tasks)"
          "sbatch is not on PATH: submit it on the cluster with: sbatch ${OUT}/sweep.sbatch"
          "--out ${OUT} --report")
file(READ "${OUT}/sweep.sbatch" script)
lbdem_expect_in("sweep.sbatch" "${script}" "#SBATCH --array=0-3\n" "#SBATCH --partition='short'\n"
          "#SBATCH --time=0:10:00\n" "#SBATCH --cpus-per-task=2\n" "--set 'grains.seed=2'")
lbdem_run_ok(ignored bash -n "${OUT}/sweep.sbatch")
# Task 0 finds its run finished; task 3, its folder gone, runs it again.
lbdem_run_ok(task0 ${CMAKE_COMMAND} -E env SLURM_ARRAY_TASK_ID=0 bash "${OUT}/sweep.sbatch")
lbdem_expect_in("task 0" "${task0}" "${OUT}/loose_0deg_dry_s1: finished")
file(REMOVE_RECURSE "${OUT}/loose_5deg_dry_s2")
lbdem_run_ok(task3 ${CMAKE_COMMAND} -E env SLURM_ARRAY_TASK_ID=3 bash "${OUT}/sweep.sbatch")
file(READ "${OUT}/loose_5deg_dry_s2/summary.json" summary)
if(NOT summary MATCHES "\"finished\": true")
    message(FATAL_ERROR "task 3 did not run loose_5deg_dry_s2 to its end: ${summary}")
endif()

# A seed listed twice is bad input: exit 2, naming the file, the line and the key.
execute_process(COMMAND "${LBDEM}" sweep "${BAD}" --out "${OUT}/bad" RESULT_VARIABLE code ERROR_VARIABLE err)
if(NOT code EQUAL 2 OR NOT err MATCHES "bad_seeds.toml:4" OR NOT err MATCHES "seeds" OR NOT err MATCHES "twice")
    message(FATAL_ERROR "expected exit 2 naming bad_seeds.toml:4 and seeds, got ${code}: ${err}")
endif()
