# Shared by the install tests (cmake -P scripts): run a command or fail with its output, and the
# flags a consumer of a sanitizer build needs.

# run(COMMAND ...): run it; any failure fails the test with the command's output.
function(run)
	execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
	if(NOT status EQUAL 0)
		message(FATAL_ERROR "failed (${status}): ${ARGN}\n${out}\n${err}")
	endif()
	message(STATUS "${out}")
endfunction()

# A sanitizer build installs an instrumented library: its consumer needs the same runtime.
set(consumer_flags "")
if(SANITIZE)
	set(consumer_flags -DCMAKE_CXX_FLAGS=-fsanitize=${SANITIZE} -DCMAKE_EXE_LINKER_FLAGS=-fsanitize=${SANITIZE})
endif()

# A fresh WORK_DIR with the package from BUILD_DIR installed into WORK_DIR/prefix.
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})
run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${WORK_DIR}/prefix)
