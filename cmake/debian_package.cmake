# The Debian package: `cpack -G DEB` in a build folder makes
# msp-stereo_<version>_<arch>.deb. Everything installs under
# /usr/lib/msp-stereo (bin/ holds msp_stereo, the tools and the `colmap`
# dispatcher), never in /usr/bin, so Debian's own colmap is not shadowed; a
# user puts /usr/lib/msp-stereo/bin first on PATH to get `colmap msp_stereo`.
# `cmake --install` keeps its usual <prefix>/bin. The Python module, when
# built, goes where python3 finds it: /usr/lib/python3/dist-packages.
set(CPACK_PACKAGE_NAME msp-stereo)
set(CPACK_PACKAGE_CONTACT "msp-stereo maintainers <msp-stereo@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
    "MSP-MVS dense stereo for COLMAP (colmap msp_stereo, a CPU patch_match_stereo)")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr/lib/msp-stereo)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
# The runtime libraries (OpenCV, Boost.Program_options, libstdc++, ...) come
# from dpkg-shlibdeps, so the list follows what the binaries really link; the
# dispatcher needs the real COLMAP, which no binary links.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "colmap")
# The Python module (python/CMakeLists.txt) goes to Debian's python3 folder,
# /usr/lib/python3/dist-packages (its component python_deb), not under the
# prefix (component python, for `cmake --install`). The components are
# packed into the one package. The module needs its python3, and numpy for
# read_array: recommended, since the programs need neither.
set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_COMPONENTS_GROUPING ALL_COMPONENTS_IN_ONE)
set(CPACK_COMPONENTS_ALL Unspecified)
if(MSP_PYTHON_FOUND)
  list(APPEND CPACK_COMPONENTS_ALL python_deb)
  # The module is built for one python3 (its ABI tag names it, e.g. cpython-311).
  math(EXPR MSP_PYTHON_NEXT_MINOR "${Python3_VERSION_MINOR} + 1")
  set(CPACK_DEBIAN_PACKAGE_RECOMMENDS
      "python3 (>= ${Python3_VERSION_MAJOR}.${Python3_VERSION_MINOR}), python3 (<< ${Python3_VERSION_MAJOR}.${MSP_PYTHON_NEXT_MINOR}), python3-numpy")
endif()
include(CPack)
