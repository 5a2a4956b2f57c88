# SPDX-License-Identifier: LGPL-2.1-or-later
# The OpenCASCADE toolkits (shared libraries, imported targets of OCCT's CMake package) the
# core links, by OCCT version: 7.6 (Debian 12, FreeCAD 0.20) and 7.8 (Debian 13, FreeCAD
# 1.0). OCCT 7.8 merged its data-exchange toolkits: STEP is TKDESTEP (was TKSTEP,
# TKSTEPBase, TKSTEPAttr, TKSTEP209, TKXDESTEP), IGES TKDEIGES (was TKIGES, TKXDEIGES), STL
# TKDESTL (was TKSTL), and the glTF writer moved from TKRWMesh to TKDEGLTF.
#   SLICEFORM_OCCT_MODELING       geometry, topology, algorithms (the same names in both)
#   SLICEFORM_OCCT_DATA_EXCHANGE  STEP/IGES/STL reading, STEP and glTF writing, XCAF
set(SLICEFORM_OCCT_MODELING
    TKernel TKMath TKG2d TKG3d TKGeomBase TKBRep TKGeomAlgo TKTopAlgo TKPrim TKBO TKShHealing
    TKMesh TKOffset)
if(OpenCASCADE_VERSION VERSION_GREATER_EQUAL 7.8)
  set(SLICEFORM_OCCT_DATA_EXCHANGE
      TKXSBase TKDESTEP TKDEIGES TKDESTL TKDEGLTF TKRWMesh TKXCAF TKLCAF TKCAF)
else()
  set(SLICEFORM_OCCT_DATA_EXCHANGE
      TKXSBase TKSTEP TKIGES TKXDESTEP TKXDEIGES TKSTL TKRWMesh TKXCAF TKLCAF TKCAF)
endif()
foreach(_tk IN LISTS SLICEFORM_OCCT_MODELING SLICEFORM_OCCT_DATA_EXCHANGE)
  if(NOT TARGET ${_tk})
    message(FATAL_ERROR "OpenCASCADE ${OpenCASCADE_VERSION} has no toolkit ${_tk}: its -dev "
                        "packages (scripts/setup) are missing, or this OCCT version is not known here")
  endif()
endforeach()
message(STATUS "OpenCASCADE ${OpenCASCADE_VERSION}: data exchange ${SLICEFORM_OCCT_DATA_EXCHANGE}")
