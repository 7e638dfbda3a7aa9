# Unpacks the CAD meshes of Debian's libcgal-demo (fandisk, anchor_dense, blade, rotor,
# pinion, couplingdown, ...) into the build tree, where tests, examples and the program
# find them. FS_MESH_DIR is that folder.
set(FEATURE_SEGMENTATION_CGAL_DATA_ARCHIVE "/usr/share/doc/libcgal-dev/data.tar.gz"
    CACHE FILEPATH "CGAL's data archive (Debian package libcgal-demo)")
set(FS_MESH_DIR "${CMAKE_BINARY_DIR}/data/meshes")
set(FS_MESHES fandisk.off anchor_dense.off blade.off rotor.off pinion.off couplingdown.off
              cube.off cube_quad.off sphere.off elephant.off)
set(_fs_stamp "${FS_MESH_DIR}/fandisk.off")
if(NOT EXISTS "${_fs_stamp}")
  if(NOT EXISTS "${FEATURE_SEGMENTATION_CGAL_DATA_ARCHIVE}")
    message(FATAL_ERROR
      "CGAL's data archive was not found at ${FEATURE_SEGMENTATION_CGAL_DATA_ARCHIVE}. "
      "Install Debian's libcgal-demo (scripts/install_dependencies.sh does) or set "
      "FEATURE_SEGMENTATION_CGAL_DATA_ARCHIVE.")
  endif()
  set(_patterns)
  foreach(m ${FS_MESHES})
    list(APPEND _patterns "data/meshes/${m}")
  endforeach()
  file(ARCHIVE_EXTRACT INPUT "${FEATURE_SEGMENTATION_CGAL_DATA_ARCHIVE}"
       DESTINATION "${CMAKE_BINARY_DIR}" PATTERNS ${_patterns})
  message(STATUS "Feature_segmentation: unpacked CGAL meshes into ${FS_MESH_DIR}")
endif()
