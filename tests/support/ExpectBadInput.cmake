# Runs `lbdem info CASE` and checks the bad-input contract: exit code 2 and one sentence that
# names the file, the line and the suggested key. Usage: cmake -DLBDEM=... -DCASE=... -P this.
include("${CMAKE_CURRENT_LIST_DIR}/CommandChecks.cmake")
get_filename_component(name "${CASE}" NAME)
lbdem_expect_exit(2 MATCHES "${name}:5:" "fluid\\.tau'" COMMAND "${LBDEM}" info "${CASE}")
