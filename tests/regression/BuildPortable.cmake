# Configures the portable preset once and brings its lbdem up to date (the golden runs' binary).
# Usage: cmake -DSOURCE=source-dir -P BuildPortable.cmake
if(NOT EXISTS "${SOURCE}/build/portable/CMakeCache.txt")
    execute_process(COMMAND ${CMAKE_COMMAND} --preset portable WORKING_DIRECTORY "${SOURCE}"
                    OUTPUT_QUIET RESULT_VARIABLE code)
    if(NOT code EQUAL 0)
        message(FATAL_ERROR "configuring the portable preset failed (exit ${code})")
    endif()
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build --preset portable WORKING_DIRECTORY "${SOURCE}"
                RESULT_VARIABLE code)
if(NOT code EQUAL 0)
    message(FATAL_ERROR "building the portable lbdem failed (exit ${code})")
endif()
