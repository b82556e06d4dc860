# Install b2analytic from BUILD_DIR into a scratch prefix, build the consumer project in
# SOURCE_DIR/tests/install/consumer against it, and run it. Any failure fails the test.
include(${CMAKE_CURRENT_LIST_DIR}/InstallSupport.cmake)

run(${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/install/consumer -B ${WORK_DIR}/build
	-DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix -DCMAKE_BUILD_TYPE=Release ${consumer_flags})
run(${CMAKE_COMMAND} --build ${WORK_DIR}/build)
run(${WORK_DIR}/build/consumer)
