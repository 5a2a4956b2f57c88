# SPDX-License-Identifier: LGPL-2.1-or-later
# The Debian package freecad-sliceform (issue 15), made by `cpack` in the build folder
# (scripts/package). It installs for every user of the Debian release it is built on:
#   /usr/share/freecad/Mod/Sliceform/   the workbench (FreeCAD's system Mod folder)
#   /usr/lib/python3/dist-packages/     the compiled core, built for that release's Python
#   /usr/bin/sliceform                  the command line program
# These install rules are the component `deb`, left out of a plain `cmake --install`
# (which installs the workbench into one user's Mod folder, as before).
set(SLICEFORM_DEB_MOD_DIR "share/freecad/Mod" CACHE STRING
    "FreeCAD's system Mod folder, relative to /usr, for the Debian package")
set(SLICEFORM_DEB_PYTHON_DIR "lib/python3/dist-packages" CACHE STRING
    "The system Python's module folder, relative to /usr, for the Debian package")
set(_mod "${SLICEFORM_DEB_MOD_DIR}/Sliceform")

install(FILES Init.py InitGui.py package.xml LICENSE README.md DESTINATION "${_mod}"
        COMPONENT deb EXCLUDE_FROM_ALL)
install(DIRECTORY App/sliceform_app DESTINATION "${_mod}/App" COMPONENT deb EXCLUDE_FROM_ALL
        PATTERN "__pycache__" EXCLUDE)
install(DIRECTORY Gui/sliceform_gui DESTINATION "${_mod}/Gui" COMPONENT deb EXCLUDE_FROM_ALL
        PATTERN "__pycache__" EXCLUDE)
install(DIRECTORY Resources DESTINATION "${_mod}" COMPONENT deb EXCLUDE_FROM_ALL)
install(FILES LICENSE DESTINATION share/doc/freecad-sliceform RENAME copyright
        COMPONENT deb EXCLUDE_FROM_ALL)
install(TARGETS sliceform RUNTIME DESTINATION bin COMPONENT deb EXCLUDE_FROM_ALL)
if(SLICEFORM_BUILD_PYTHON)
  install(TARGETS sliceform_native LIBRARY DESTINATION "${SLICEFORM_DEB_PYTHON_DIR}"
          COMPONENT deb EXCLUDE_FROM_ALL)
endif()

# Which Debian release this is (the package is built for the FreeCAD, OCCT and Python of
# that release, and only installs there).
set(_os_id "")
set(_os_version "")
if(EXISTS /etc/os-release)
  file(STRINGS /etc/os-release _os_lines)
  foreach(_line IN LISTS _os_lines)
    if(_line MATCHES "^ID=\"?([^\"]*)\"?$")
      set(_os_id "${CMAKE_MATCH_1}")
    elseif(_line MATCHES "^VERSION_ID=\"?([^\"]*)\"?$")
      set(_os_version "${CMAKE_MATCH_1}")
    endif()
  endforeach()
endif()

# The FreeCAD the package needs: the one installed here, at least its major.minor version.
set(_freecad_version "0.20")
find_program(DPKG_QUERY dpkg-query)
if(DPKG_QUERY)
  execute_process(COMMAND ${DPKG_QUERY} -W -f=\${Version} freecad-python3
                  OUTPUT_VARIABLE _fc RESULT_VARIABLE _fc_result ERROR_QUIET)
  if(_fc_result EQUAL 0 AND _fc MATCHES "^([0-9]+:)?([0-9]+\\.[0-9]+)")
    set(_freecad_version "${CMAKE_MATCH_2}")
  endif()
endif()

set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME freecad-sliceform)
set(CPACK_PACKAGE_VERSION "${PROJECT_VERSION}")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "FreeCAD workbench that designs paper sliceforms")
set(CPACK_PACKAGE_DESCRIPTION
    "Turns a solid (CAD part, PartDesign body or closed mesh) into a paper sliceform: two\
 families of slotted patches that slide together into a stable lattice and fold flat. A\
 parametric FreeCAD feature with a sketch per patch and TechDraw sheets, DXF/SVG/PDF layouts\
 for printers and laser cutters, and the sliceform command line program.")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
# Only the component `deb`, from this build folder.
set(CPACK_INSTALL_CMAKE_PROJECTS "${CMAKE_BINARY_DIR};Sliceform;deb;/")
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "Sliceform developers")
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
if(_os_id STREQUAL "debian" AND _os_version)
  set(CPACK_DEBIAN_PACKAGE_RELEASE "1~deb${_os_version}")
else()
  set(CPACK_DEBIAN_PACKAGE_RELEASE 1)
endif()
# The shared libraries (OCCT of this release, cairo, NLopt, dxflib, ...) from dpkg-shlibdeps;
# FreeCAD and the Python the module is built for by hand.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "freecad-python3 (>= ${_freecad_version})")
if(SLICEFORM_BUILD_PYTHON)
  math(EXPR _py_next "${Python3_VERSION_MINOR} + 1")
  string(APPEND CPACK_DEBIAN_PACKAGE_DEPENDS
         ", python3 (>= ${Python3_VERSION_MAJOR}.${Python3_VERSION_MINOR})"
         ", python3 (<< ${Python3_VERSION_MAJOR}.${_py_next})")
endif()
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS freecad)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)  # freecad-sliceform_<version>-<release>_<arch>.deb
set(CPACK_OUTPUT_FILE_PREFIX "${CMAKE_BINARY_DIR}/packages")
include(CPack)
