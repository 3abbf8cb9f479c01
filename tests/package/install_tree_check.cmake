# The install tree as a user meets it (tests/package/CMakeLists.txt registers the steps with ctest).
#   cmake -DSTEP=install|consumer|laws-alone|build-tree|command|python|options-off|subproject -DFRICTIONLAB_SOURCE_DIR=... -DFRICTIONLAB_BUILD_DIR=... \
#         -DWORK_DIR=... -DCONSUMER_SOURCE_DIR=... -DCXX_COMPILER=... [-DCXX_COMPILER_LAUNCHER=...] \
#         [-DBUILD_TYPE=...] [-DCONSUMER_FLAGS=...] [-DPYTHON=... -DPYTHON_DIR=...] -P install_tree_check.cmake
# install:  a fresh `cmake --install` into WORK_DIR/prefix; the files a user needs are there, and
#           every installed header's "..." includes resolve inside the installed include folder.
# consumer: tests/consumer configured with CMAKE_PREFIX_PATH=prefix (find_package), built and run.
# build-tree: tests/consumer configured against the build tree's package (frictionlab_DIR=build).
# command:  the installed `frictionlab paper` run from a folder without data/ reads the installed
#           scenarios, not the source tree's; so does `frictionlab simulate NAME`; --version.
# python:   the installed Python package (PYTHON_DIR under the prefix) imported by PYTHON from
#           elsewhere: it is the installed one, and evaluates exact at Omega = 0 (F1 = k N).
# options-off, subproject: frictionlab configured with tests and benchmarks off, and added to
#           another project with add_subdirectory, on a machine without GoogleTest and Google
#           Benchmark (CMAKE_DISABLE_FIND_PACKAGE_*): no test or benchmark target is generated.
cmake_minimum_required(VERSION 3.25)

foreach(var STEP FRICTIONLAB_SOURCE_DIR FRICTIONLAB_BUILD_DIR WORK_DIR CONSUMER_SOURCE_DIR CXX_COMPILER)
  if(NOT DEFINED ${var} OR "${${var}}" STREQUAL "")
    message(FATAL_ERROR "install_tree_check.cmake: -D${var}=... is required")
  endif()
endforeach()
set(prefix ${WORK_DIR}/prefix)

# Runs a command; stops with its output on failure.
function(run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err
                  WORKING_DIRECTORY ${run_dir})
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${what} failed (${rc}):\n${ARGN}\n${out}\n${err}")
  endif()
  set(run_output "${out}" PARENT_SCOPE)
endfunction()
# The command that configures a consumer project `source` in a fresh `build` against the installed
# prefix, as frictionlab was built (compiler, flags, build type, launcher), into `out`.
function(consumer_configure_command source build out)
  file(REMOVE_RECURSE ${build})
  set(c ${CMAKE_COMMAND} -S ${source} -B ${build} -DCMAKE_PREFIX_PATH=${prefix}
        -DCMAKE_CXX_COMPILER=${CXX_COMPILER} "-DCMAKE_CXX_FLAGS=${CONSUMER_FLAGS}")
  if(BUILD_TYPE)
    list(APPEND c -DCMAKE_BUILD_TYPE=${BUILD_TYPE})
  endif()
  if(CXX_COMPILER_LAUNCHER)
    list(APPEND c -DCMAKE_CXX_COMPILER_LAUNCHER=${CXX_COMPILER_LAUNCHER})
  endif()
  set(${out} ${c} PARENT_SCOPE)
endfunction()
set(run_dir ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})

if(STEP STREQUAL "install")
  file(REMOVE_RECURSE ${prefix})
  run("cmake --install" ${CMAKE_COMMAND} --install ${FRICTIONLAB_BUILD_DIR} --prefix ${prefix})
  # GNUInstallDirs may choose lib/ or lib64/ (or lib/<arch> under /usr): find the package there.
  file(GLOB_RECURSE config LIST_DIRECTORIES false ${prefix}/*/frictionlabConfig.cmake)
  if(NOT config)
    message(FATAL_ERROR "no frictionlabConfig.cmake under ${prefix}")
  endif()
  get_filename_component(config_dir ${config} DIRECTORY)
  foreach(f bin/frictionlab include/friction/law.h include/friction/registry.h include/dynamics/body/simulation.h
            include/dynamics/body/scenario.h include/dynamics/core/run_loop.h
            share/frictionlab/scenarios/sphere-sliding.toml
            share/frictionlab/scenarios/egg-printed-a.toml share/frictionlab/friction-examples.csv
            share/doc/frictionlab/LICENSE)
    if(NOT EXISTS ${prefix}/${f})
      message(FATAL_ERROR "not installed: ${prefix}/${f}")
    endif()
  endforeach()
  foreach(f frictionlabConfigVersion.cmake frictionlabTargets.cmake frictionlabFrictionTargets.cmake frictionlabDependencies.cmake)
    if(NOT EXISTS ${config_dir}/${f})
      message(FATAL_ERROR "not installed: ${config_dir}/${f}")
    endif()
  endforeach()
  # The exported targets name nothing that exists only in the build: the warning flags, the
  # sanitizers, the source or build folders.
  file(GLOB targets_files ${config_dir}/frictionlabTargets*.cmake)
  foreach(f IN LISTS targets_files)
    file(READ ${f} text)
    foreach(leak frictionlab_warnings frictionlab::warnings -fsanitize ${FRICTIONLAB_BUILD_DIR}
                 ${FRICTIONLAB_SOURCE_DIR})
      string(FIND "${text}" "${leak}" at)
      if(NOT at EQUAL -1)
        message(FATAL_ERROR "${f} mentions '${leak}', which exists only in frictionlab's build")
      endif()
    endforeach()
  endforeach()
  # Every project header an installed header includes is installed too.
  file(GLOB_RECURSE headers RELATIVE ${prefix}/include ${prefix}/include/*.h)
  foreach(h IN LISTS headers)
    file(STRINGS ${prefix}/include/${h} includes REGEX "^[ \t]*#[ \t]*include[ \t]*\"")
    foreach(line IN LISTS includes)
      string(REGEX REPLACE "^[^\"]*\"([^\"]+)\".*$" "\\1" inc "${line}")
      if(NOT EXISTS ${prefix}/include/${inc})
        message(FATAL_ERROR "installed header ${h} includes \"${inc}\", which is not installed")
      endif()
    endforeach()
  endforeach()
  list(LENGTH headers n)
  message(STATUS "installed into ${prefix}: ${n} headers, package in ${config_dir}")

elseif(STEP STREQUAL "consumer")
  set(build ${WORK_DIR}/consumer-build)
  consumer_configure_command(${CONSUMER_SOURCE_DIR} ${build} configure)
  run("configuring the consumer" ${configure})
  run("building the consumer" ${CMAKE_COMMAND} --build ${build})
  run("running the consumer" ${build}/frictionlab_consumer)
  message(STATUS "${run_output}")

elseif(STEP STREQUAL "laws-alone")
  # The laws alone: COMPONENTS friction with every package the rest of frictionlab needs made
  # unfindable (the config must not ask for them), built and run, and no GSL (GPL-3) in what the
  # program loads.
  set(build ${WORK_DIR}/laws-consumer-build)
  consumer_configure_command(${FRICTIONLAB_SOURCE_DIR}/tests/consumer_friction ${build} configure)
  foreach(p GSL Boost Eigen3 tomlplusplus nlohmann_json Threads)
    list(APPEND configure -DCMAKE_DISABLE_FIND_PACKAGE_${p}=ON)
  endforeach()
  run("configuring the laws' consumer" ${configure})
  run("building the laws' consumer" ${CMAKE_COMMAND} --build ${build} --verbose)
  string(FIND "${run_output}" "gsl" linked_gsl)
  if(NOT linked_gsl EQUAL -1)
    message(FATAL_ERROR "the laws' consumer is linked with GSL:\n${run_output}")
  endif()
  run("running the laws' consumer" ${build}/frictionlab_laws_consumer)
  message(STATUS "${run_output}")
  run("ldd of the laws' consumer" ldd ${build}/frictionlab_laws_consumer)
  string(FIND "${run_output}" "libgsl" loads_gsl)
  if(NOT loads_gsl EQUAL -1)
    message(FATAL_ERROR "the laws' consumer loads GSL:\n${run_output}")
  endif()
  message(STATUS "the laws' consumer links no GSL:\n${run_output}")

elseif(STEP STREQUAL "build-tree")
  # Configure only: the consumer's code and link line are those of the installed package.
  set(build ${WORK_DIR}/consumer-build-tree)
  file(REMOVE_RECURSE ${build})
  run("configuring the consumer against the build tree" ${CMAKE_COMMAND} -S ${CONSUMER_SOURCE_DIR} -B ${build}
      -Dfrictionlab_DIR=${FRICTIONLAB_BUILD_DIR} -DCMAKE_CXX_COMPILER=${CXX_COMPILER})
  message(STATUS "the consumer configures against ${FRICTIONLAB_BUILD_DIR}")

elseif(STEP STREQUAL "command")
  # A folder without data/scenarios, so that only the installed scenarios can be found.
  set(run_dir ${WORK_DIR}/command-cwd)
  file(REMOVE_RECURSE ${run_dir})
  file(MAKE_DIRECTORY ${run_dir})
  run("the installed frictionlab paper" ${prefix}/bin/frictionlab paper --out out --laws coulomb-decoupled
      --eggs egg-printed --cases a --no-baseline --no-figures --jobs 1 --set run.t_end=0.01)
  # Every run writes the scenario file it read on the first line of its scenario.toml.
  file(STRINGS ${run_dir}/out/runs/egg-printed-a/coulomb-decoupled/scenario.toml first LIMIT_COUNT 1)
  file(REAL_PATH ${prefix}/share/frictionlab/scenarios/egg-printed-a.toml expected)
  if(NOT first MATCHES "^# (.*) resolved")
    message(FATAL_ERROR "unexpected first line of scenario.toml: ${first}")
  endif()
  file(REAL_PATH ${CMAKE_MATCH_1} read)
  if(NOT read STREQUAL expected)
    message(FATAL_ERROR "the installed command read ${read}, not the installed ${expected}")
  endif()
  message(STATUS "the installed command read ${read}")
  # A shipped scenario by name, from that folder: the installed one.
  run("the installed frictionlab simulate sphere-sliding" ${prefix}/bin/frictionlab simulate sphere-sliding
      --set run.t_end=0.01 --out sim)
  file(STRINGS ${run_dir}/sim/scenario.toml first LIMIT_COUNT 1)
  file(REAL_PATH ${prefix}/share/frictionlab/scenarios/sphere-sliding.toml expected)
  if(NOT first MATCHES "^# (.*) resolved")
    message(FATAL_ERROR "unexpected first line of scenario.toml: ${first}")
  endif()
  file(REAL_PATH ${CMAKE_MATCH_1} read)
  if(NOT read STREQUAL expected)
    message(FATAL_ERROR "simulate sphere-sliding read ${read}, not the installed ${expected}")
  endif()
  run("frictionlab --version" ${prefix}/bin/frictionlab --version)
  if(NOT run_output MATCHES "^frictionlab [0-9]+\\.[0-9]+\\.[0-9]+\n$")
    message(FATAL_ERROR "frictionlab --version printed '${run_output}'")
  endif()

elseif(STEP STREQUAL "python")
  set(package ${prefix}/${PYTHON_DIR}/frictionlab)
  file(GLOB core ${package}/_core*.so)
  if(NOT EXISTS ${package}/__init__.py OR NOT core)
    message(FATAL_ERROR "the Python package is not installed in ${package}")
  endif()
  # Pure sliding (Omega = 0): F1 = k N = 0.5 * 2 exactly, F2 = M = 0 (friction/law.h).
  set(check "import frictionlab, os, sys
where = os.path.realpath(frictionlab.__file__)
assert where.startswith(os.path.realpath(sys.argv[1])), where
F1, F2, M = frictionlab.Law('exact')(1.0, 0.0, 0.01, 0.005, 0.3, 2.0, 0.5)
assert (F1, F2, M) == (1.0, 0.0, 0.0), (F1, F2, M)
print('imported', where)")
  run("importing the installed Python package" ${CMAKE_COMMAND} -E env PYTHONPATH=${prefix}/${PYTHON_DIR}
      ${PYTHON} -c "${check}" ${package})
  message(STATUS "${run_output}")

elseif(STEP STREQUAL "options-off" OR STEP STREQUAL "subproject")
  # Configure only, on a machine "without" GoogleTest and Google Benchmark.
  set(build ${WORK_DIR}/${STEP})
  file(REMOVE_RECURSE ${build})
  set(configure ${CMAKE_COMMAND} -B ${build} -DCMAKE_CXX_COMPILER=${CXX_COMPILER}
                -DCMAKE_DISABLE_FIND_PACKAGE_GTest=ON -DCMAKE_DISABLE_FIND_PACKAGE_benchmark=ON)
  if(STEP STREQUAL "options-off")
    run("configuring with tests and benchmarks off" ${configure} -S ${FRICTIONLAB_SOURCE_DIR}
        -DBUILD_TESTING=OFF -DFRICTIONLAB_BUILD_BENCHMARKS=OFF)
    set(ours ${build})
  else()
    run("configuring a project that adds frictionlab with add_subdirectory" ${configure}
        -S ${FRICTIONLAB_SOURCE_DIR}/tests/package/subproject -DFRICTIONLAB_SOURCE_DIR=${FRICTIONLAB_SOURCE_DIR})
    set(ours ${build}/frictionlab)
  endif()
  # No test or benchmark is generated; the accuracy study (a library of the command) still is.
  foreach(absent tests bench/CMakeFiles/friction_bench.dir)
    if(EXISTS ${ours}/${absent})
      message(FATAL_ERROR "${STEP}: ${ours}/${absent} was generated")
    endif()
  endforeach()
  foreach(present bench/accuracy/CMakeFiles/accuracy_study.dir dynamics/cli/CMakeFiles/frictionlab.dir)
    if(NOT EXISTS ${ours}/${present})
      message(FATAL_ERROR "${STEP}: ${ours}/${present} was not generated")
    endif()
  endforeach()
  message(STATUS "${STEP}: configured without GoogleTest and Google Benchmark")

else()
  message(FATAL_ERROR "STEP=${STEP}: expected install, consumer, laws-alone, build-tree, command, python, options-off or subproject")
endif()
