# The test install_consumer (cmake -P): installs the build tree BUILD_DIR into WORK_DIR/prefix,
# configures and builds examples/consumer against it from scratch (find_package(wattswath)) and
# runs the program it builds, so the installed package cannot rot. Variables: SOURCE_DIR, BUILD_DIR,
# WORK_DIR, CXX_COMPILER and (may be empty) COMPILER_LAUNCHER.
foreach(var SOURCE_DIR BUILD_DIR WORK_DIR CXX_COMPILER)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "install_consumer.cmake: pass -D${var}=...")
  endif()
endforeach()

# Runs a command, echoing it; stops the test with the command and its exit status on failure.
function(step)
  string(REPLACE ";" " " line "${ARGN}")
  message(STATUS "install_consumer: ${line}")
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "install_consumer: exit status ${rc} from: ${line}")
  endif()
endfunction()

file(REMOVE_RECURSE ${WORK_DIR})
step(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${WORK_DIR}/prefix)
step(${CMAKE_COMMAND} -S ${SOURCE_DIR}/examples/consumer -B ${WORK_DIR}/consumer
  -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix -DCMAKE_CXX_COMPILER=${CXX_COMPILER}
  -DCMAKE_CXX_COMPILER_LAUNCHER=${COMPILER_LAUNCHER})
step(${CMAKE_COMMAND} --build ${WORK_DIR}/consumer)
step(${WORK_DIR}/consumer/leg_and_turn ${SOURCE_DIR}/data/vehicles/iris.json)
