# `lbdem study` refuses bad input before any run starts: exit code 2, one sentence naming the
# key, value or metric, and no output folder. Usage: cmake -DLBDEM=... -DCASE=... -DOUT=... -P this.
file(REMOVE_RECURSE "${OUT}")
include("${CMAKE_CURRENT_LIST_DIR}/CommandChecks.cmake")
# Runs `lbdem study CASE --out OUT ARGN`: exit 2, one line matching `expected`, no output folder.
function(expect_bad expected)
    lbdem_expect_exit(2 MATCHES "${expected}" NO_STDOUT
                      COMMAND "${LBDEM}" study "${CASE}" --out "${OUT}" ${ARGN})
    if(EXISTS "${OUT}")
        message(FATAL_ERROR "${ARGN}: a run was started (${OUT} exists)")
    endif()
endfunction()
expect_bad("key 'flow\\.node': unknown key; did you mean 'flow\\.nodes'\\?" --vary flow.node=8,16)
expect_bad("'abc' is not a whole number" --vary flow.nodes=8,abc)
expect_bad("'0\\.5x' is not a number" --vary fluid.tau=0.6,0.5x)
expect_bad("key 'flow\\.nodes': 2 is out of range" --vary flow.nodes=2,8)
expect_bad("no such number in summary\\.json; did you mean 'l2_error'\\?" --vary flow.nodes=8,16 --metric l2_eror)
expect_bad("no analytic or published value for u_max_m_s" --vary flow.nodes=8,16 --metric u_max_m_s
           --reference analytic)
expect_bad("expected KEY=V1,V2" --vary 8,16)
expect_bad("key 'flow\\.nodes': the key is varied twice" --vary flow.nodes=8,16 --vary flow.nodes=32,64)
expect_bad("key 'flow\\.reynolds': 0 derives the Reynolds number" --vary flow.nodes=8,16
           --set flow.reynolds=0 --set flow.tau=0)
