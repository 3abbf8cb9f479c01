# install() and export() rules. `cmake --install build --prefix P` installs
#   P/include/friction/..., P/include/dynamics/<folder>/*.h   the public headers, same include layout
#   P/lib/libfrictionlab_*.a                         the libraries of friction/ and dynamics/
#   P/bin/frictionlab                                the command
#   P/share/frictionlab/                             data/: scenarios/*.toml, friction-examples.csv
#   P/share/doc/frictionlab/LICENSE
#   P/lib/cmake/frictionlab/                         frictionlabConfig.cmake, its version file, the
#                                                    exported targets frictionlab::<name>
# so that another project does find_package(frictionlab CONFIG REQUIRED) and links
# frictionlab::friction, frictionlab::dynamics, ... The build tree is a package too (export()):
# -Dfrictionlab_DIR=<build> uses it without installing.
#
# What is installed is decided by folder, for libraries and headers alike: friction/ with its
# subfolders, and the libraries defined in dynamics/CMakeLists.txt with the headers of the folders
# they are built from (dynamics/core, io, shapes, contact, body); the models, studies and the
# command in dynamics/puck/, tippe_top/, paper/, ensemble/, cli/ (like bench/accuracy/) are not. A library added to these folders is installed and
# exported under its target name (or its EXPORT_NAME), which must also be its frictionlab:: alias.

include(CMakePackageConfigHelpers)

set(FRICTIONLAB_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/frictionlab)

# The library targets defined in `dir` (and in its subfolders with RECURSE), into `out`.
function(frictionlab_libraries_in dir out)
  cmake_parse_arguments(ARG "RECURSE" "" "" ${ARGN})
  set(found)
  get_property(targets DIRECTORY ${dir} PROPERTY BUILDSYSTEM_TARGETS)
  foreach(t IN LISTS targets)
    get_target_property(type ${t} TYPE)
    if(type MATCHES "^(STATIC|SHARED|OBJECT|INTERFACE)_LIBRARY$")
      list(APPEND found ${t})
    endif()
  endforeach()
  if(ARG_RECURSE)
    get_property(subdirs DIRECTORY ${dir} PROPERTY SUBDIRECTORIES)
    foreach(sub IN LISTS subdirs)
      frictionlab_libraries_in(${sub} more RECURSE)
      list(APPEND found ${more})
    endforeach()
  endif()
  set(${out} ${found} PARENT_SCOPE)
endfunction()

# Prepares an installed library: its exported name must be its alias in the build tree (one name
# for users of either tree), its file name says whose it is, and its build-only links stay out of
# its exported interface.
function(frictionlab_prepare_export target)
  get_target_property(name ${target} EXPORT_NAME)
  if(NOT name)
    set(name ${target})
  endif()
  set(aliased "")
  if(TARGET frictionlab::${name})
    get_target_property(aliased frictionlab::${name} ALIASED_TARGET)
  endif()
  if(NOT aliased STREQUAL target)
    message(FATAL_ERROR "library '${target}' is installed as frictionlab::${name}, but that is not its "
                        "alias: add `add_library(frictionlab::${name} ALIAS ${target})`, or set its "
                        "EXPORT_NAME to the name of its alias")
  endif()
  # Installed beside other projects' libraries: lib/libfrictionlab_<name>.a, not lib/libdynamics.a.
  set_target_properties(${target} PROPERTIES OUTPUT_NAME frictionlab_${name})
  # A static library records its PRIVATE links in its interface as $<LINK_ONLY:...>. For the
  # warning flags (frictionlab::warnings, an interface target of compile options only) that entry
  # links nothing; drop it so that neither export names a target that is for building frictionlab
  # only. (CMake 3.26's $<BUILD_LOCAL_INTERFACE:...> in each link line would say the same.)
  get_target_property(links ${target} INTERFACE_LINK_LIBRARIES)
  if(links)
    list(FILTER links EXCLUDE REGEX "^\\$<LINK_ONLY:(frictionlab::warnings|frictionlab_warnings)>$")
    # A build-only link (header-only Boost of the laws) would be exported as an empty $<LINK_ONLY:>.
    list(FILTER links EXCLUDE REGEX "^\\$<LINK_ONLY:\\$<BUILD_INTERFACE:[^>]*>>$")
    set_target_properties(${target} PROPERTIES INTERFACE_LINK_LIBRARIES "${links}")
  endif()
endfunction()

frictionlab_libraries_in(${PROJECT_SOURCE_DIR}/friction friction_libraries RECURSE)
frictionlab_libraries_in(${PROJECT_SOURCE_DIR}/dynamics dynamics_libraries)
set(FRICTIONLAB_INSTALLED_LIBRARIES ${friction_libraries} ${dynamics_libraries})
foreach(t IN LISTS FRICTIONLAB_INSTALLED_LIBRARIES)
  frictionlab_prepare_export(${t})
endforeach()

# Two export sets: the laws (component `friction`, the libraries marked FRICTIONLAB_COMPONENT
# friction in friction/CMakeLists.txt: they need no other package) and the rest (component
# `dynamics`: the simulations, their I/O, exact-reference, the command; Eigen, GSL, Boost, toml++,
# nlohmann-json).
set(law_libraries)
set(other_libraries)
foreach(t IN LISTS FRICTIONLAB_INSTALLED_LIBRARIES)
  get_target_property(component ${t} FRICTIONLAB_COMPONENT)
  if(component STREQUAL "friction")
    list(APPEND law_libraries ${t})
  else()
    list(APPEND other_libraries ${t})
  endif()
endforeach()
install(TARGETS ${law_libraries}
        EXPORT frictionlabFrictionTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(TARGETS ${other_libraries} frictionlab
        EXPORT frictionlabTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})

# Headers, from the same folders as the libraries.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/friction/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/friction
        FILES_MATCHING PATTERN "*.h")
foreach(folder core io shapes contact body)
  file(GLOB dynamics_headers CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/dynamics/${folder}/*.h)
  install(FILES ${dynamics_headers} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/dynamics/${folder})
endforeach()

# The shipped data, where the installed command looks for it (dynamics/io/shipped_data.h).
install(DIRECTORY ${PROJECT_SOURCE_DIR}/data/ DESTINATION ${FRICTIONLAB_INSTALL_DATADIR})
install(FILES ${PROJECT_SOURCE_DIR}/LICENSE DESTINATION ${CMAKE_INSTALL_DOCDIR})

# The package: targets, config, version. 0.y.z: a new minor version may break the interface.
install(EXPORT frictionlabFrictionTargets NAMESPACE frictionlab:: DESTINATION ${FRICTIONLAB_INSTALL_CMAKEDIR})
install(EXPORT frictionlabTargets NAMESPACE frictionlab:: DESTINATION ${FRICTIONLAB_INSTALL_CMAKEDIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/frictionlabConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
set(frictionlab_config_data_dir ${FRICTIONLAB_INSTALL_DATADIR})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/frictionlabConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/package/frictionlabConfig.cmake
                              INSTALL_DESTINATION ${FRICTIONLAB_INSTALL_CMAKEDIR}
                              PATH_VARS frictionlab_config_data_dir)
install(FILES ${PROJECT_BINARY_DIR}/package/frictionlabConfig.cmake
              ${PROJECT_BINARY_DIR}/frictionlabConfigVersion.cmake
              ${PROJECT_SOURCE_DIR}/cmake/frictionlabDependencies.cmake
        DESTINATION ${FRICTIONLAB_INSTALL_CMAKEDIR})

# The build tree as a package: the same files in ${PROJECT_BINARY_DIR}, data from the source tree.
export(EXPORT frictionlabFrictionTargets NAMESPACE frictionlab:: FILE ${PROJECT_BINARY_DIR}/frictionlabFrictionTargets.cmake)
export(EXPORT frictionlabTargets NAMESPACE frictionlab:: FILE ${PROJECT_BINARY_DIR}/frictionlabTargets.cmake)
set(frictionlab_config_data_dir ${PROJECT_SOURCE_DIR}/data)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/frictionlabConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/frictionlabConfig.cmake
                              INSTALL_DESTINATION ${PROJECT_BINARY_DIR} INSTALL_PREFIX ${PROJECT_BINARY_DIR}
                              PATH_VARS frictionlab_config_data_dir)
configure_file(${PROJECT_SOURCE_DIR}/cmake/frictionlabDependencies.cmake
               ${PROJECT_BINARY_DIR}/frictionlabDependencies.cmake COPYONLY)
