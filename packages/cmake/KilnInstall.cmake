# Install rules and the Debian package (CPack): `cmake --install build --prefix PREFIX` puts
#   PREFIX/bin/kiln, kiln-diff, kiln_contact_box_report   the programs
#   PREFIX/share/kiln/inputs/                             the example decks
#   PREFIX/share/doc/kiln/                                README.md and doc/
# and `cpack -G DEB --config build/CPackConfig.cmake` makes kiln_VERSION_ARCH.deb, whose Depends
# dpkg-shlibdeps computes from the libraries the programs link (Trilinos, Open MPI, HDF5,
# Exodus, METIS, ...), plus python3-h5py and python3-numpy for kiln-diff.
include(GNUInstallDirs)

# Kiln's own libraries are static; the installed programs find the shared ones (Trilinos,
# HDF5, ...) where they were linked from (Debian's are on the loader's path anyway).
set_target_properties(kiln kiln_contact_box_report PROPERTIES
  INSTALL_RPATH_USE_LINK_PATH TRUE
  INSTALL_RPATH "$ORIGIN/../${CMAKE_INSTALL_LIBDIR}")
install(TARGETS kiln kiln_contact_box_report RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(PROGRAMS ${PROJECT_SOURCE_DIR}/tools/kiln-diff DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/inputs/ DESTINATION ${CMAKE_INSTALL_DATADIR}/kiln/inputs)
install(FILES ${PROJECT_SOURCE_DIR}/README.md DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/kiln)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/doc/ DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/kiln)

set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME kiln)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_CONTACT "Kiln developers")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
  "Coupled thermo-mechanics with contact on Trilinos (heat, thermo-elasticity, gap contact)")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
# Depends from the shared libraries the programs link (dpkg-shlibdeps), and kiln-diff's Python.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "python3, python3-h5py, python3-numpy, openmpi-bin")
include(CPack)
