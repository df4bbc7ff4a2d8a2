# Helpers that give every lbdem target the same warnings, tuning and sanitizer flags.

# Apply the project's compile options to TARGET (warnings, -march, sanitizer).
function(lbdem_configure_target target)
    target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic)
    # sqrt need not set errno: without this flag a loop calling std::sqrt cannot be vectorised.
    target_compile_options(${target} PRIVATE -fno-math-errno)
    if(LBDEM_STRICT)
        target_compile_options(${target} PRIVATE -Werror)
    endif()
    if(LBDEM_NATIVE)
        target_compile_options(${target} PRIVATE -march=native)
    endif()
    if(LBDEM_SANITIZER)
        target_compile_options(${target} PRIVATE -fsanitize=${LBDEM_SANITIZER} -fno-omit-frame-pointer)
        target_link_options(${target} PRIVATE -fsanitize=${LBDEM_SANITIZER})
        # Undefined behaviour fails the test that meets it instead of printing and going on.
        if(LBDEM_SANITIZER MATCHES "undefined")
            target_compile_options(${target} PRIVATE -fno-sanitize-recover=undefined)
        endif()
    endif()
endfunction()

# lbdem_library(NAME ALIAS SOURCES ... PUBLIC_LIBS ... PRIVATE_LIBS ...): a static module library.
function(lbdem_library name)
    cmake_parse_arguments(ARG "" "ALIAS" "SOURCES;PUBLIC_LIBS;PRIVATE_LIBS" ${ARGN})
    add_library(${name} STATIC ${ARG_SOURCES})
    if(ARG_ALIAS)
        add_library(${ARG_ALIAS} ALIAS ${name})
    endif()
    target_include_directories(${name} PUBLIC "${PROJECT_SOURCE_DIR}")
    target_link_libraries(${name} PUBLIC ${ARG_PUBLIC_LIBS} PRIVATE ${ARG_PRIVATE_LIBS})
    set_target_properties(${name} PROPERTIES POSITION_INDEPENDENT_CODE ON)
    lbdem_configure_target(${name})
endfunction()
