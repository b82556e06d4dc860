# The README's C++ programs as a user builds them: install b2analytic from BUILD_DIR into a
# scratch prefix, write the README's blocks (and the files its fragments come from) into a
# project with EXTRACTOR (b2a_readme_programs), build it against the installed package, and run
# every program. Any failure fails the test.
include(${CMAKE_CURRENT_LIST_DIR}/InstallSupport.cmake)

run(${EXTRACTOR} ${SOURCE_DIR}/README.md ${SOURCE_DIR} ${WORK_DIR}/project)
run(${CMAKE_COMMAND} -S ${WORK_DIR}/project -B ${WORK_DIR}/build
	-DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix -DCMAKE_BUILD_TYPE=Release ${consumer_flags})
run(${CMAKE_COMMAND} --build ${WORK_DIR}/build)
file(STRINGS ${WORK_DIR}/project/programs.txt programs)
foreach(program IN LISTS programs)
	run(${WORK_DIR}/build/${program})
endforeach()
