# Install and package (issue 13): `cmake --install build [--prefix P]` and `cpack -G DEB`.
# Layout under the prefix (default /opt/refloc), the same as a checkout's where it matters:
#   bin/<service and tool binaries>   deploy/refloc, services.list, supervisord.conf, ...
#   deploy/config/*.json              deploy/systemd/*    docs/, README.md, LICENSE
# The binaries find their default config as <prefix>/deploy/config (common/program_version's
# refloc_root: the ancestor of bin/ that holds deploy/config); deploy/refloc uses <prefix>/bin
# when it exists. Tests, benchmarks and test helpers are not installed.
include_guard(GLOBAL)

if(CMAKE_INSTALL_PREFIX_INITIALIZED_TO_DEFAULT)
  set(CMAKE_INSTALL_PREFIX /opt/refloc CACHE PATH "refloc install prefix" FORCE)
endif()

# Every executable defined under services/ and tools/ (not tests/).
function(refloc_install_executables_in dir)
  get_property(targets DIRECTORY ${dir} PROPERTY BUILDSYSTEM_TARGETS)
  foreach(t ${targets})
    get_target_property(type ${t} TYPE)
    if(type STREQUAL "EXECUTABLE")
      install(TARGETS ${t} RUNTIME DESTINATION bin)
    endif()
  endforeach()
  get_property(subdirs DIRECTORY ${dir} PROPERTY SUBDIRECTORIES)
  foreach(sub ${subdirs})
    refloc_install_executables_in(${sub})
  endforeach()
endfunction()
foreach(dir ${service_dirs} ${CMAKE_SOURCE_DIR}/tools)
  if(EXISTS ${dir}/CMakeLists.txt)
    refloc_install_executables_in(${dir})
  endif()
endforeach()

install(PROGRAMS deploy/refloc deploy/run_mission.sh deploy/lcm-spy.sh DESTINATION deploy)
install(FILES deploy/services.list deploy/supervisord.conf DESTINATION deploy)
install(DIRECTORY deploy/config/ DESTINATION deploy/config FILES_MATCHING PATTERN "*.json")
install(DIRECTORY deploy/systemd/ DESTINATION deploy/systemd)
# run_mission.sh runs the stack in a private network namespace through this script.
install(PROGRAMS tests/tools/run_in_netns.sh DESTINATION deploy)
install(DIRECTORY docs/ DESTINATION docs)
# web_console serves its page from <root>/services/web_console/www (shipped_path).
install(DIRECTORY services/web_console/www/ DESTINATION services/web_console/www)
# run_mission.sh and refloc-eval draw their pictures with it (<root>/tools/refloc-plot).
install(PROGRAMS tools/refloc-plot/refloc-plot.py tools/refloc-plot/residual_correlation.py
        DESTINATION tools/refloc-plot)
install(FILES tools/refloc-plot/refloc_plot_data.py tools/refloc-plot/refloc_plot_draw.py tools/refloc-plot/refloc_plot_plan.py
              tools/refloc-plot/refloc_plot_studies.py tools/refloc-plot/README.md DESTINATION tools/refloc-plot)
# refloc-survey drive draws its report with this script (<root>/tools/refloc-survey).
install(PROGRAMS tools/refloc-survey/survey_drive_plot.py DESTINATION tools/refloc-survey)
install(FILES README.md DESTINATION .)
if(EXISTS ${CMAKE_SOURCE_DIR}/LICENSE)
  install(FILES LICENSE DESTINATION .)
endif()
if(REFLOC_LCMTYPES_JAR)
  # deploy/lcm-spy.sh reads $REFLOC_BUILD/share/java/refloc_lcmtypes.jar.
  install(FILES ${REFLOC_LCMTYPES_JAR} DESTINATION share/java OPTIONAL)
endif()

# `make install` and cpack's preinstall step must not build the whole tree (every test and
# benchmark): they install what was built, and fail naming a binary that was not.
set(CMAKE_SKIP_INSTALL_ALL_DEPENDENCY ON)

set(CPACK_PACKAGE_NAME refloc)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_VENDOR "refloc team")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
    "Reflector localization for a Mecanum robot with a SICK LMS100 (LCM services)")
set(CPACK_PACKAGE_DESCRIPTION
    "refloc localizes a four-Mecanum-wheel robot from a SICK LMS100 and cylindrical retro-reflectors: \
one LCM process per stage (driver, extraction, matching, pose solving, odometry, fusion, navigator), \
a simulator, offline tools, supervisord and systemd units. Installs under /opt/refloc.")
set(CPACK_PACKAGING_INSTALL_PREFIX /opt/refloc)
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "refloc team <refloc@example.org>")
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
# Debian 12 runtime packages of what the binaries link and the scripts call.
set(CPACK_DEBIAN_PACKAGE_DEPENDS
    "liblcm1, liblcm-bin, libspdlog1.10, libfmt9, libceres3, libsystemd0, supervisor, python3, iproute2, util-linux, jq")
set(CPACK_STRIP_FILES ON)
set(CPACK_GENERATOR DEB)
include(CPack)
