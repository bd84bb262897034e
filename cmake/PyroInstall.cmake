# Install rules and the package config (included from CMakeLists.txt after the modules exist).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(PYRO_INSTALL_INCLUDEDIR ${CMAKE_INSTALL_INCLUDEDIR}/pyrocumulus)
set(PYRO_INSTALL_DATADIR ${CMAKE_INSTALL_DATADIR}/pyrocumulus)
set(PYRO_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/Pyrocumulus)

foreach(layer engine components systems)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${layer} DESTINATION ${PYRO_INSTALL_INCLUDEDIR}
          FILES_MATCHING PATTERN "*.h")
endforeach()
# The applications' modules (tools/viewer, tools/bench, ...; not the command line, tools/pyro):
# their headers at "tools/<name>/...".
get_property(PYRO_TOOL_MODULE_FOLDERS GLOBAL PROPERTY PYRO_TOOL_MODULE_FOLDERS)
foreach(folder IN LISTS PYRO_TOOL_MODULE_FOLDERS)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${folder}/ DESTINATION ${PYRO_INSTALL_INCLUDEDIR}/${folder}
          FILES_MATCHING PATTERN "*.h")
endforeach()
# Shaders, data tables, scenes and sample volumes.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/content/ DESTINATION ${PYRO_INSTALL_DATADIR})
# Baked by the default_flipbook target (built with `all`).
install(DIRECTORY ${PYRO_DEFAULT_FLIPBOOK_DIR} DESTINATION ${PYRO_INSTALL_DATADIR}/flipbooks)

pyro_export_set(window PYRO_WINDOW_MODULES PYRO_WINDOW_FIND)
install(TARGETS pyro_engine pyro_glm ${PYRO_ENGINE_MODULES} EXPORT PyrocumulusTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${PYRO_INSTALL_INCLUDEDIR})
install(EXPORT PyrocumulusTargets NAMESPACE Pyrocumulus:: DESTINATION ${PYRO_INSTALL_CMAKEDIR})
install(TARGETS ${PYRO_WINDOW_MODULES} EXPORT PyrocumulusWindowTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${PYRO_INSTALL_INCLUDEDIR})
install(EXPORT PyrocumulusWindowTargets NAMESPACE Pyrocumulus::
        DESTINATION ${PYRO_INSTALL_CMAKEDIR})

# engine/core/content_location.cpp is compiled again by the package config with the installed
# paths (Pyrocumulus::content_location), so the installed engine finds the installed content
# wherever the package lands.
install(FILES ${PROJECT_SOURCE_DIR}/engine/core/content_location.cpp
        DESTINATION ${PYRO_INSTALL_CMAKEDIR})
set(PYRO_CONFIG_FIND_ENGINE "${PYRO_ENGINE_FIND}")
set(PYRO_CONFIG_FIND_WINDOW "${PYRO_WINDOW_FIND}")
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/PyrocumulusConfig.cmake.in
  ${PROJECT_BINARY_DIR}/PyrocumulusConfig.cmake
  INSTALL_DESTINATION ${PYRO_INSTALL_CMAKEDIR}
  PATH_VARS PYRO_INSTALL_INCLUDEDIR PYRO_INSTALL_DATADIR)
# 0.x: a minor version may break the API.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/PyrocumulusConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/PyrocumulusConfig.cmake
              ${PROJECT_BINARY_DIR}/PyrocumulusConfigVersion.cmake
        DESTINATION ${PYRO_INSTALL_CMAKEDIR})
