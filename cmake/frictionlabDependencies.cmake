# The packages frictionlab's installed libraries need. The libraries are static, so their private
# dependencies are needed too by whoever links them. One list, read twice: by CMakeLists.txt (to
# build, with find_package) and by the installed frictionlabConfig.cmake (with find_dependency);
# the includer defines frictionlab_find_dependency().
frictionlab_find_dependency(Eigen3 3.3 NO_MODULE)
frictionlab_find_dependency(GSL)
frictionlab_find_dependency(Boost 1.74 CONFIG)
frictionlab_find_dependency(tomlplusplus CONFIG)
frictionlab_find_dependency(nlohmann_json 3.11 CONFIG)
frictionlab_find_dependency(Threads)
