# Install rules and the CMake package (find_package(phongrast CONFIG)).
# Included at the end of the top-level CMakeLists.txt when PHONGRAST_INSTALL is ON,
# so every target below already exists; the optional ones (I/O library, command-line
# program) are installed only when this build made them.
#
#   <prefix>/include/phongrast/            public headers (+ the generated version.hpp)
#   <prefix>/lib/libphongrast.a            and libphongrast_io.a when built
#   <prefix>/bin/phongrast                 the command-line program when built
#   <prefix>/lib/phongrast/phongrast_openimageio.so   OpenImageIO, loaded on first use (with the I/O library)
#   <prefix>/lib/phongrast/phongrast_openexr.so       OpenEXR, loaded on the first EXR read or write (likewise)
#   <prefix>/share/thumbnailers/phongrast.thumbnailer the desktop thumbnailer (with the program)
#   <prefix>/share/mime/packages/phongrast-mesh-mime.xml  the PLY MIME type Debian 12 lacks
#   <prefix>/share/phongrast/              the example assets/ when present
#   <prefix>/lib/cmake/phongrast/          phongrastConfig.cmake, its version file, the targets
include(CMakePackageConfigHelpers)

# tests/consumers/CMakeLists.txt expects the package files here too.
set(PHONGRAST_INSTALL_CMAKEDIR "${CMAKE_INSTALL_LIBDIR}/cmake/phongrast")

# Users write phongrast::phongrast and phongrast::io, whatever the build target names are.
set_target_properties(phongrast PROPERTIES EXPORT_NAME phongrast)
set(phongrast_exported_targets phongrast)
if(TARGET phongrast_io)
  set_target_properties(phongrast_io PROPERTIES EXPORT_NAME io)
  list(APPEND phongrast_exported_targets phongrast_io)
endif()

# Include directories come from each target's $<INSTALL_INTERFACE:include> (src/CMakeLists.txt).
install(TARGETS ${phongrast_exported_targets}
  EXPORT phongrastTargets
  ARCHIVE DESTINATION "${CMAKE_INSTALL_LIBDIR}" COMPONENT phongrast_development
  LIBRARY DESTINATION "${CMAKE_INSTALL_LIBDIR}" COMPONENT phongrast_runtime
  RUNTIME DESTINATION "${CMAKE_INSTALL_BINDIR}" COMPONENT phongrast_runtime
)

# Public headers. The I/O headers go only with the I/O library: installing them
# without it would give users headers whose functions link nowhere.
install(DIRECTORY "${PROJECT_SOURCE_DIR}/include/phongrast"
  DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}"
  COMPONENT phongrast_development
  FILES_MATCHING PATTERN "*.hpp"
  PATTERN "io" EXCLUDE
  PATTERN "io.hpp" EXCLUDE
)
if(TARGET phongrast_io AND IS_DIRECTORY "${PROJECT_SOURCE_DIR}/include/phongrast/io")
  install(DIRECTORY "${PROJECT_SOURCE_DIR}/include/phongrast/io"
    DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}/phongrast"
    COMPONENT phongrast_development
    FILES_MATCHING PATTERN "*.hpp"
  )
  # The io library's umbrella header, beside phongrast.hpp.
  install(FILES "${PROJECT_SOURCE_DIR}/include/phongrast/io.hpp"
    DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}/phongrast"
    COMPONENT phongrast_development)
endif()
install(FILES "${PROJECT_BINARY_DIR}/include/phongrast/version.hpp"
  DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}/phongrast"
  COMPONENT phongrast_development
)

# The OpenImageIO module (src/io/openimageio_module.hpp): loaded on first use,
# found next to the program or library holding phongrast::io, or here.
if(TARGET phongrast_openimageio)
  install(TARGETS phongrast_openimageio
    LIBRARY DESTINATION "${CMAKE_INSTALL_LIBDIR}/phongrast" COMPONENT phongrast_runtime)
endif()
# The OpenEXR module (src/io/openexr_module.hpp), likewise.
if(TARGET phongrast_openexr)
  install(TARGETS phongrast_openexr
    LIBRARY DESTINATION "${CMAKE_INSTALL_LIBDIR}/phongrast" COMPONENT phongrast_runtime)
endif()

# The command-line program is a tool, not something to link: installed, not exported.
if(TARGET phongrast_cli)
  install(TARGETS phongrast_cli
    RUNTIME DESTINATION "${CMAKE_INSTALL_BINDIR}" COMPONENT phongrast_runtime)
  # The freedesktop thumbnailer: written at install time so that Exec names the
  # program where this install put it (cmake --install --prefix included).
  set(phongrast_mesh_mime_types
      "model/obj;model/stl;model/x.stl-ascii;model/x.stl-binary;model/gltf+json;model/gltf-binary;model/x-ply;")
  install(CODE "
    set(program \"\${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_BINDIR}/phongrast\")
    file(WRITE \"\${CMAKE_CURRENT_BINARY_DIR}/phongrast.thumbnailer\"
         \"[Thumbnailer Entry]\\nTryExec=\${program}\\nExec=\${program} thumbnail %i %o --size %s\\nMimeType=${phongrast_mesh_mime_types}\\n\")
    file(INSTALL DESTINATION \"\${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_DATADIR}/thumbnailers\"
         TYPE FILE FILES \"\${CMAKE_CURRENT_BINARY_DIR}/phongrast.thumbnailer\")"
    COMPONENT phongrast_runtime)
  install(FILES "${PROJECT_SOURCE_DIR}/cmake/phongrast-mesh-mime.xml"
    DESTINATION "${CMAKE_INSTALL_DATADIR}/mime/packages" COMPONENT phongrast_runtime)
endif()

if(IS_DIRECTORY "${PROJECT_SOURCE_DIR}/assets")
  install(DIRECTORY "${PROJECT_SOURCE_DIR}/assets/"
    DESTINATION "${CMAKE_INSTALL_DATADIR}/phongrast"
    COMPONENT phongrast_runtime)
endif()

install(EXPORT phongrastTargets
  NAMESPACE phongrast::
  FILE phongrastTargets.cmake
  DESTINATION "${PHONGRAST_INSTALL_CMAKEDIR}"
  COMPONENT phongrast_development
)

# phongrast_find_dependency_lines(<target> <out>): a find_dependency() line for each
# package whose imported target <target> links, PUBLIC or PRIVATE (a static
# library's private links reach the user's link line as $<LINK_ONLY:...>). Read
# from the target itself so a dependency added in src/ cannot be forgotten here.
# The package is the namespace of the imported target (glm::glm -> glm, TBB::tbb -> TBB).
# An imported target without a namespace (xsimd) is its own package name when it is
# visible here; targets imported in a subdirectory are not, so prefer Namespace:: names.
# Plain library names (m, pthread) need no package.
function(phongrast_find_dependency_lines target out)
  get_target_property(links ${target} LINK_LIBRARIES)
  set(packages "")
  foreach(item IN LISTS links)
    if(item MATCHES "^phongrast(::|_|$)")
      continue()  # ours: install(EXPORT) insists they are exported too
    elseif(item MATCHES "^PkgConfig::(.+)$")
      # pkg_check_modules(<prefix> IMPORTED_TARGET <module>): here the prefix is the module's name.
      list(APPEND packages "PkgConfig:${CMAKE_MATCH_1}")
    elseif(item MATCHES "^([A-Za-z0-9_]+)::")
      list(APPEND packages "${CMAKE_MATCH_1}")
    elseif(TARGET "${item}")
      get_target_property(imported "${item}" IMPORTED)
      if(imported)
        list(APPEND packages "${item}")
      endif()
    endif()
  endforeach()
  list(REMOVE_DUPLICATES packages)
  set(lines "")
  foreach(package IN LISTS packages)
    if(package MATCHES "^PkgConfig:(.+)$")
      string(APPEND lines "find_dependency(PkgConfig)\n"
                          "pkg_check_modules(${CMAKE_MATCH_1} REQUIRED IMPORTED_TARGET ${CMAKE_MATCH_1})\n")
      continue()
    elseif(package STREQUAL "JPEG")
      string(APPEND lines "find_dependency(JPEG)\n")  # CMake's own FindJPEG: no config file
      continue()
    endif()
    string(APPEND lines "find_dependency(${package} CONFIG)\n")
    if(package STREQUAL "OpenImageIO")
      # Drops the /usr/include/opencv4 entry Debian's OpenImageIO config names even
      # when that folder is missing (file installed next to phongrastConfig.cmake).
      string(APPEND lines "include(\"\${CMAKE_CURRENT_LIST_DIR}/PhongrastOpenImageIO.cmake\")\n"
                          "phongrast_find_openimageio()\n")
    endif()
  endforeach()
  set(${out} "${lines}" PARENT_SCOPE)
endfunction()

# Read by phongrastConfig.cmake.in.
phongrast_find_dependency_lines(phongrast PHONGRAST_CORE_DEPENDENCIES)
if(TARGET phongrast_io)
  set(PHONGRAST_PACKAGE_HAS_IO ON)
  phongrast_find_dependency_lines(phongrast_io PHONGRAST_IO_DEPENDENCIES)
else()
  set(PHONGRAST_PACKAGE_HAS_IO OFF)
  set(PHONGRAST_IO_DEPENDENCIES "")
endif()
configure_package_config_file(
  "${PROJECT_SOURCE_DIR}/cmake/phongrastConfig.cmake.in"
  "${PROJECT_BINARY_DIR}/package/phongrastConfig.cmake"
  INSTALL_DESTINATION "${PHONGRAST_INSTALL_CMAKEDIR}"
  NO_SET_AND_CHECK_MACRO
)
# SameMajorVersion: a request for X.Y is met by an installed X.Z with Z >= Y.
write_basic_package_version_file(
  "${PROJECT_BINARY_DIR}/package/phongrastConfigVersion.cmake"
  VERSION "${PROJECT_VERSION}"
  COMPATIBILITY SameMajorVersion
)
install(FILES
  "${PROJECT_BINARY_DIR}/package/phongrastConfig.cmake"
  "${PROJECT_BINARY_DIR}/package/phongrastConfigVersion.cmake"
  DESTINATION "${PHONGRAST_INSTALL_CMAKEDIR}"
  COMPONENT phongrast_development
)
if(TARGET phongrast_io)
  # phongrastConfig.cmake includes it when a user asks for the io component.
  install(FILES "${PROJECT_SOURCE_DIR}/cmake/PhongrastOpenImageIO.cmake"
    DESTINATION "${PHONGRAST_INSTALL_CMAKEDIR}"
    COMPONENT phongrast_development
  )
endif()
