# FindExodusII: the Exodus II C library (Debian: libexodusii-dev, 6.02 on netCDF).
# Defines ExodusII::ExodusII.
find_path(ExodusII_INCLUDE_DIR exodusII.h)
find_library(ExodusII_LIBRARY NAMES exoIIv2c exodus)
find_library(NetCDF_LIBRARY netcdf)
if(ExodusII_INCLUDE_DIR AND EXISTS "${ExodusII_INCLUDE_DIR}/exodusII.h")
  file(STRINGS "${ExodusII_INCLUDE_DIR}/exodusII.h" _ex_vers REGEX "#define EX_API_VERS ")
  string(REGEX MATCH "[0-9]+\\.[0-9]+" ExodusII_VERSION "${_ex_vers}")
endif()
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(ExodusII
  REQUIRED_VARS ExodusII_LIBRARY NetCDF_LIBRARY ExodusII_INCLUDE_DIR
  VERSION_VAR ExodusII_VERSION)
if(ExodusII_FOUND AND NOT TARGET ExodusII::ExodusII)
  add_library(ExodusII::ExodusII UNKNOWN IMPORTED)
  set_target_properties(ExodusII::ExodusII PROPERTIES IMPORTED_LOCATION "${ExodusII_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${ExodusII_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "${NetCDF_LIBRARY}")
endif()
mark_as_advanced(ExodusII_INCLUDE_DIR ExodusII_LIBRARY NetCDF_LIBRARY)
