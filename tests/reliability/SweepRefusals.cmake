# `lbdem sweep` refuses before anything is created or run: two cases with one name (they would
# share a folder), a case that fails to parse; a case that fails at start is reported as failed
# with its first error line, not as missing with zeros. Usage: cmake -DLBDEM=... -DOUT=... -P this.
file(REMOVE_RECURSE "${OUT}")
file(MAKE_DIRECTORY "${OUT}")

# A small dry case called name, with extra TOML lines appended to its [domain] section.
function(write_case file name domain)
    file(WRITE "${OUT}/${file}" "schema = 1\nname = \"${name}\"\n[domain]\n${domain}\n[fluid]\nenabled = false\n"
               "[grains]\ncount = 150\npacking = 0.79\n[run]\nend_tc = 0.25\n")
endfunction()

# Runs a sweep of the given case files into OUT/runs; sets code, out and err in the caller.
macro(sweep cases)
    file(WRITE "${OUT}/sweep.toml" "sweep = 1\ncases = [${cases}]\n")
    execute_process(COMMAND "${LBDEM}" sweep "${OUT}/sweep.toml" --out "${OUT}/runs" --progress-every 0
                    RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 600)
endmacro()

write_case(first.toml same "")
write_case(second.toml same "")
sweep("\"first.toml\", \"second.toml\"")
if(NOT code EQUAL 2 OR NOT err MATCHES "second\\.toml.*'same'.*first\\.toml" OR EXISTS "${OUT}/runs")
    message(FATAL_ERROR "two cases named alike must be refused naming both files, before any run (${code}):\n${out}${err}")
endif()
write_case(good.toml good "")
file(WRITE "${OUT}/broken.toml" "schema = 1\n[grains]\ncuont = 3\n")
sweep("\"good.toml\", \"broken.toml\"")
if(NOT code EQUAL 2 OR NOT err MATCHES "broken\\.toml:3" OR EXISTS "${OUT}/runs")
    message(FATAL_ERROR "a case that fails to parse must be refused before anything is created (${code}):\n${out}${err}")
endif()
# The column of 150 grains (about 23 mm wide) does not fit a 15 mm domain: the run fails at start.
write_case(narrow.toml narrow "width_m = 0.015")
sweep("\"good.toml\", \"narrow.toml\"")
file(READ "${OUT}/runs/sweep.csv" csv)
file(READ "${OUT}/runs/sweep.md" md)
if(NOT code EQUAL 1 OR NOT out MATCHES "narrow FAILED in [0-9]+ s: lbdem: .*does not fit the domain")
    message(FATAL_ERROR "a case that fails at start must be reported with its error (${code}):\n${out}${err}")
endif()
if(NOT csv MATCHES "\nnarrow,0\\.79,5\\.0,dry,failed,,,,,,,\n" OR NOT csv MATCHES "\ngood,0\\.79,5\\.0,dry,finished,")
    message(FATAL_ERROR "sweep.csv must list narrow as failed with no figures:\n${csv}")
endif()
if(NOT md MATCHES "## Failed cases\n\n- narrow: lbdem: .*does not fit the domain")
    message(FATAL_ERROR "sweep.md must give narrow's error:\n${md}")
endif()
# Variants: a name that cannot name a folder, a name twice, an unknown key, a variant whose
# overrides are bad; each refused with the sweep file's line (or the case's key) before any run.
macro(variant_refused body expected)
    file(WRITE "${OUT}/sweep.toml" "sweep = 1\ncases = [\"good.toml\"]\n${body}")
    file(REMOVE_RECURSE "${OUT}/runs")
    execute_process(COMMAND "${LBDEM}" sweep "${OUT}/sweep.toml" --out "${OUT}/runs" --progress-every 0
                    RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 600)
    if(NOT code EQUAL 2 OR NOT err MATCHES "${expected}" OR EXISTS "${OUT}/runs")
        message(FATAL_ERROR "a bad variant must be refused before any run, matching '${expected}' (${code}):\n${out}${err}")
    endif()
endmacro()
variant_refused("[[variants]]\nname = \"a/b\"\n" "sweep.toml:4.*variants.name")
variant_refused("[[variants]]\nname = \"a\"\n[[variants]]\nname = \"a\"\n" "sweep.toml:[56].*variants.name.*twice")
variant_refused("[[variants]]\nname = \"a\"\nsett = []\n" "sweep.toml:5.*variants.sett.*did you mean 'set'")
variant_refused("variants = 3\n" "sweep.toml:3.*variants")
variant_refused("[[variants]]\nname = \"a\"\nset = [\"grains.cuont=3\"]\n" "cuont")
# Folder names must not collide through variants: case a with variant b__c and case a__b with
# variant c would both run into OUT/a__b__c, and so would case a_ with b and case a with _b.
write_case(a.toml a "")
write_case(ab.toml a__b "")
file(WRITE "${OUT}/sweep.toml" "sweep = 1\ncases = [\"a.toml\", \"ab.toml\"]\n"
           "[[variants]]\nname = \"c\"\n[[variants]]\nname = \"b__c\"\n")
file(REMOVE_RECURSE "${OUT}/runs")
execute_process(COMMAND "${LBDEM}" sweep "${OUT}/sweep.toml" --out "${OUT}/runs" --progress-every 0
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 600)
if(NOT code EQUAL 2 OR NOT err MATCHES "sweep.toml:6.*variants.name.*'__'" OR EXISTS "${OUT}/runs")
    message(FATAL_ERROR "variants whose folders collide must be refused before any run (${code}):\n${out}${err}")
endif()
variant_refused("[[variants]]\nname = \"_b\"\n" "sweep.toml:4.*variants.name.*not starting with '_'")
# --report gathers from a folder that exists; a missing one is bad input, and nothing is created.
file(WRITE "${OUT}/sweep.toml" "sweep = 1\ncases = [\"good.toml\"]\n")
execute_process(COMMAND "${LBDEM}" sweep "${OUT}/sweep.toml" --out "${OUT}/absent" --report
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 60)
if(NOT code EQUAL 2 OR NOT err MATCHES "--out .*absent is not a folder: there is nothing to gather"
   OR EXISTS "${OUT}/absent")
    message(FATAL_ERROR "--report on a missing folder must be refused as bad input (${code}):\n${out}${err}")
endif()
message(STATUS "ok: sweep refusals and failures")
